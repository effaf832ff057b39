// The reference solver: Boost.Odeint's controlled runge_kutta_fehlberg78 (order 8
// with embedded 7) on the continuous vector field, stepping adaptively from each
// step time to the next so that every observed state is at t_k exactly (the role
// of the paper's DOP853 with tight tolerances).
#pragma once

#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/methods/one_step_method.h>

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace ddb {

/// The continuous vector field as an odeint system on real coordinates: std::array for
/// fixed-size groups, std::vector for matrix groups (the entries of the N×N matrix,
/// real and imaginary parts interleaved for complex ones, as std::complex stores them).
namespace detail {
template <class G, bool kDynamic = isDynamicGroup<G>>
struct OdeintState {
  using type = std::array<double, G::kDim>;
};
template <class G>
struct OdeintState<G, true> {
  using type = std::vector<double>;
};
/// x of `reals` entries: a std::vector is resized, a std::array has its size.
inline void resizeOdeintState(std::vector<double>& x, std::size_t reals) { x.resize(reals); }
template <std::size_t kReals>
void resizeOdeintState(std::array<double, kReals>&, std::size_t) {}
}  // namespace detail

template <class G>
struct OdeintSystem {
  using Dual = typename G::template Dual<double>;
  using Scalar = typename Dual::Scalar;
  static constexpr int kReals = sizeof(Scalar) / sizeof(double);
  using State = typename detail::OdeintState<G>::type;
  /// The kept workspaces of the in-place field (LiePoissonSystem::vectorFieldInto).
  struct Workspace {
    Dual input, output;
    FieldWorkspace<G> field;
  };
  const LiePoissonSystem<G>& system;
  Eigen::Index rows, cols;
  /// The kept workspaces of a matrix group's field (ReferenceSolver's).
  Workspace* workspace = nullptr;

  static auto map(State& x, Eigen::Index rows, Eigen::Index cols) {
    return Eigen::Map<Dual>(reinterpret_cast<Scalar*>(x.data()), rows, cols);
  }
  static auto map(const State& x, Eigen::Index rows, Eigen::Index cols) {
    return Eigen::Map<const Dual>(reinterpret_cast<const Scalar*>(x.data()), rows, cols);
  }
  /// A fixed-size state's field by value, in registers, as odeint's std::array state asks
  /// (inlined into odeint's stepper: ddb-bench's odeint-rk4 peer); a matrix state's in place,
  /// in the kept workspaces.
  void operator()(const State& x, State& dxdt, double) const {
    if constexpr (hasFixedSize<Dual>) {
      map(dxdt, rows, cols) = system.vectorField(Dual(map(x, rows, cols)));
    } else {
      workspace->input = map(x, rows, cols);
      system.vectorFieldInto(workspace->input, workspace->field, workspace->output);
      map(dxdt, rows, cols) = workspace->output;
    }
  }
};

// GCC 12 flags the copy of a default-constructed stepper inside odeint's
// controlled_runge_kutta constructor (-Wuninitialized): a false positive in Boost. Clang, which
// reads GCC's pragmas too, knows no -Wmaybe-uninitialized and warned of an unknown option.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
template <class G>
class ReferenceSolver : public OneStepMethod<G> {
 public:
  using Dual = typename G::template Dual<double>;
  using State = typename OdeintSystem<G>::State;

  /// Sub-steps one trajectory may take, from reset() on (docs/reference/guarantees.md §1; about
  /// 2 s for the rigid body, whose Scenario B over 250 time units needs a few thousand:
  /// docs/results/benchmarks.md, "Worst-case times of the apps").
  static constexpr long kDefaultMaxSubsteps = 1'000'000;
  /// A sub-step below this fraction of max(|t|, h) advances t by round-off only: the
  /// field is too stiff (|α| = 1e308) or too fast for the tolerance, and the controller
  /// would shrink it forever.
  static constexpr double kSmallestRelativeSubstep = 1e-12;

  explicit ReferenceSolver(std::shared_ptr<const LiePoissonSystem<G>> system,
                           double tolerance = 1e-13, long max_substeps = kDefaultMaxSubsteps)
      : system_(std::move(system)),
        tolerance_(requirePositive("tolerance", tolerance)),
        max_substeps_(max_substeps),
        stepper_(typename Controlled::error_checker_type(tolerance_, tolerance_)) {
    if (max_substeps < 1)
      throwInvalid("max_substeps", std::to_string(max_substeps), "must be >= 1");
  }

  std::string name() const override { return "reference"; }
  void reset() override {
    dt_ = 0.0;
    substeps_ = 0;
  }
  /// The sub-step size carried to the next step, and the sub-steps taken.
  void saveWarmStart(BinaryRecordWriter& out) const override {
    out.tag("reference");
    out.put(dt_);
    out.put(substeps_);
  }
  void loadWarmStart(BinaryRecordReader& in, const Dual&) override {
    in.expectTag("reference");
    in.get(dt_);
    in.get(substeps_);
  }

  Dual step(const Dual& mu, double t, double h) override { return this->stepInPlace(mu, t, h); }

  /// In place; on matrix groups the state, its saved copy and the field's workspaces are kept
  /// (no allocation once the size is known, as odeint's own stepper states).
  void advance(Dual& mu, double t, double h) override {
    namespace odeint = boost::numeric::odeint;
    State& x = state_;
    detail::resizeOdeintState(x, std::size_t(mu.size() * OdeintSystem<G>::kReals));
    workspace_.field.resize(mu);
    const OdeintSystem<G> rhs{*system_, mu.rows(), mu.cols(), &workspace_};
    OdeintSystem<G>::map(x, mu.rows(), mu.cols()) = mu;
    const double end = t + h;
    double time = t;
    // First trial step: 1% of the time scale |μ|/|μ̇| (odeint's error estimate is NaN,
    // and so accepted, when a trial step overflows), never more than h.
    double dt = dt_ > 0.0 ? dt_ : firstStep(mu, h);
    int rejected = 0;
    const double smallest = kSmallestRelativeSubstep * std::max(std::abs(end), h);
    while (end - time > 1e-14 * std::abs(end)) {
      if (++substeps_ > max_substeps_ || dt < smallest) {
        throw BudgetExhausted(
            "reference solver (adaptive Runge-Kutta-Fehlberg 7(8))",
            (dt < smallest ? "sub-step " + formatValue(dt) + " below " + formatValue(smallest)
                           : std::to_string(max_substeps_) + " sub-steps in this trajectory") +
                " at t = " + formatValue(time) + " of [" + formatValue(t) + ", " +
                formatValue(end) + "] (the field is too stiff or too fast for tolerance " +
                formatValue(tolerance_) + ")",
            -1, t, h);
      }
      const bool last = time + dt >= end;
      double trial = last ? end - time : dt;
      const double before = trial;
      State& saved = saved_;
      saved = x;
      const bool accepted = stepper_.try_step(rhs, x, time, trial) == odeint::success;
      const bool finite =
          std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
      if (accepted && finite) {
        if (last) time = end;  // land on t_{k+1} exactly
        dt = (last && trial > before) ? std::max(dt, trial) : trial;
        rejected = 0;
      } else {
        if (!finite) {
          x = saved;
          if (accepted) time -= before;
          trial = 0.1 * before;
        }
        dt = trial;
        if (++rejected > 100) {
          throw SolveFailure("reference step-size control", -1, time, dt, INFINITY, tolerance_);
        }
      }
    }
    dt_ = dt;
    mu = OdeintSystem<G>::map(static_cast<const State&>(x), mu.rows(), mu.cols());
  }

 private:
  double firstStep(const Dual& mu, double h) const {
    const double rate = system_->vectorField(mu).norm();
    return std::min(h, rate > 0.0 ? 0.01 * mu.norm() / rate : h);
  }

  using Fehlberg78 = boost::numeric::odeint::runge_kutta_fehlberg78<State>;
  using Controlled = boost::numeric::odeint::controlled_runge_kutta<Fehlberg78>;

  std::shared_ptr<const LiePoissonSystem<G>> system_;
  double tolerance_;
  long max_substeps_;
  Controlled stepper_;
  double dt_ = 0.0;
  long substeps_ = 0;
  State state_{}, saved_{};
  typename OdeintSystem<G>::Workspace workspace_;
};

#pragma GCC diagnostic pop

}  // namespace ddb
