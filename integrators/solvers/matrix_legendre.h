// The discrete Legendre equation of a DDB step on a matrix group (SO(N), SU(N)), Hamiltonian
// form, solved matrix-free (docs/reference/conventions.md §2 and §4):
//   target = (dτ⁻¹_{hξ(p)})* p,  ξ = ∂H/∂μ(p),
// for p in u(N) (so(N)), not projected to su(N). The Cayley map, with a = hξ/2:
//   target = (I + a) p (I − a), by the fixed point p ← target − [a, p] + a p a (two products)
// from the guess of a CorrectionPredictor (linear prediction from the last corrections);
// when it contracts too slowly (h‖ξ‖ near 1), Newton–Krylov: GMRES on the exact
// Jacobian–vector products (four products each). The exponential (sweep() below): the fixed
// point in ξ's eigenbasis, or with the series truncated after ad^order; no Newton fallback
// (a slow sweep goes on while it contracts). ξ(p) is the system's velocity
// (LiePoissonSystem::velocityInto): the Hamiltonian sees the algebra part of p, whose trace
// stays in the solve. Workspaces are allocated on the first solve of a size and reused: no
// iteration allocates.
// The solver is written against the matrix backend (core/matrix_backend.h): the same
// algorithm runs on a LiePoissonSystem of dense matrices and of any backend's, over MPI ranks
// on the distributed fluid (distributed/distributed_zeitlin_fluid.h; docs/design/distributed.md,
// "One step formula"), the exponential's sweep in the backend's eigenbasis
// (MatrixBackend<Dual>::Eigenbasis).
//
// A solver from outside (setExternalSolver) may solve DDB's Cayley equation instead, through
// residualInto and jacobianTimes: Ceres does, as an independent check of the matrix-free
// iterations (matrix_legendre_ceres.h, which this header does not include).
//
// Convergence: an error bound of the accepted fixed-point iterate below
// relative_tolerance·‖target‖, with ρ the measured rate and the update equal to the
// residual r(p): update/(1 − ρ) for DDB's target, whose accepted iterate is the one whose
// a the update uses, ρ/(1 − ρ)·update for the others, whose accepted iterate is the next;
// or the Newton residual. Otherwise a SolveFailure with the last residual, and the caller
// keeps every state before it.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/detail/bernoulli.h>
#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/matrix_traits.h>
#include <ddb/core/skew_hermitian_eigenbasis.h>
#include <ddb/groups/cayley.h>
#include <ddb/groups/exponential.h>
#include <ddb/integrators/matrix_kernels/matrix_retraction.h>
#include <ddb/integrators/solvers/anderson_acceleration.h>
#include <ddb/integrators/solvers/correction_predictor.h>
#include <ddb/integrators/solvers/injectivity_guard.h>
#include <ddb/integrators/solvers/legendre_equation.h>
#include <ddb/integrators/solvers/legendre_stats.h>
#include <ddb/integrators/solvers/matrix_free_gmres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace ddb {

namespace detail {
/// B's Eigenbasis where a solver sweeps in it, else nothing (a backend may have none).
template <class B, bool kNeeded>
struct EigenbasisSlot {
  using type = typename B::Eigenbasis;
};
template <class B>
struct EigenbasisSlot<B, false> {
  using type = std::monostate;
};
}  // namespace detail

/// How the matrix-free solver proceeds: kAuto is the fixed point with Newton–Krylov as
/// the fallback; the others force one path (for tests and comparisons). kExternal is set by
/// setExternalSolver. kCeres, which solved by Ceres inside this solver until 0.2.0, is
/// Newton–Krylov now (the same equation to the same tolerance); Ceres is useCeres(solver) of
/// matrix_legendre_ceres.h (CHANGELOG.md, 0.2.0).
enum class MatrixLegendreStrategy {
  kAuto,
  kFixedPoint,
  kNewtonKrylov,
  kExternal,
  kCeres [[deprecated("kCeres solves by Newton-Krylov now; for Ceres call useCeres(solver) of "
                      "<ddb/integrators/solvers/matrix_legendre_ceres.h>; removed in 0.3.0")]] =
      kNewtonKrylov
};

template <class R, class System = LiePoissonSystem<typename R::Group>>
class MatrixLegendreSolver {
 public:
  using G = typename R::Group;
  using Algebra = typename System::Algebra;
  using Dual = typename System::Dual;
  using B = MatrixBackend<Dual>;
  static_assert(isDynamicGroup<G>, "MatrixLegendreSolver is the solver of matrix groups");
  /// How the retraction's fixed point is swept (matrix_retraction.h): in product form, with
  /// a certified frozen solution and Newton–Krylov (Cayley); in ξ's eigenbasis (exp); or by
  /// the truncated series.
  static constexpr MatrixSweep kSweep = MatrixRetraction<R>::kSweep;
  static constexpr bool kProductForm = kSweep == MatrixSweep::kProductForm;
  static constexpr bool kEigenbasisSweep = kSweep == MatrixSweep::kEigenbasis;
  /// Dense matrices (the Ceres cross-check needs them, matrix_legendre_ceres.h).
  static constexpr bool kDense = isEigenMatrix<Dual>;

  /// A fixed-point sweep that shrinks the update by less than this hands over to Newton.
  static constexpr double kSlowContraction = 0.5;
  static constexpr int kMaxFixedPoint = 60;
  static constexpr int kMaxNewton = 12;
  static constexpr int kMaxKrylov = 200;
  static constexpr int kMaxForcedFixedPoint = 2000;
  /// Mixed sweeps of a moving target without a new smallest update that end the solve.
  static constexpr int kStallSweeps = 10;

  MatrixLegendreSolver(const System& system, const R& retraction, LegendreForm form,
                       SolverOptions options)
      : system_(system), retraction_(retraction), form_(form), options_(options) {
    if (form_ != LegendreForm::kHamiltonian) {
      throw InvalidArgument(
          "form = lagrangian is invalid: matrix groups use the Hamiltonian form (unknown p)");
    }
  }

  void reset() {
    forgetPredictions();
    rate_ = NAN;
  }
  LegendreForm form() const { return form_; }
  const LegendreStats& stats() const { return stats_; }

  /// The warm start (OneStepMethod::saveWarmStart): the predictors with their step sizes
  /// and ages, and the last measured contraction rate. Its matrices are whole
  /// (MatrixBackend::save), so that a dense solver and a distributed one read each other's.
  void saveWarmStart(BinaryRecordWriter& out) const {
    out.tag("matrix legendre solver");
    // The state's rows and columns (0 before the first solve): the states are square.
    const auto n = static_cast<std::int64_t>(B::rows(p_));
    out.put(n);
    out.put(n);
    out.put(rate_);
    out.put(clock_);
    for (std::size_t i = 0; i < kPredictors; ++i) {
      out.put(predictor_h_[i]);
      out.put(last_used_[i]);
      predictors_[i].save(out);
    }
  }
  /// Restores what saveWarmStart wrote, for states of `like`'s size (and, distributed,
  /// layout); a record of another size is corrupt.
  void loadWarmStart(BinaryRecordReader& in, const Dual& like) {
    in.expectTag("matrix legendre solver");
    const auto rows = in.get<std::int64_t>(), cols = in.get<std::int64_t>();
    if (rows < 0 || cols != rows) throw CorruptRecord("a negative or non-square state size");
    reset();
    if (rows > 0) {
      if (B::rows(like) != rows) throw CorruptRecord("a warm start of another size than the state");
      allocate(like);
    }
    in.get(rate_);
    in.get(clock_);
    for (std::size_t i = 0; i < kPredictors; ++i) {
      in.get(predictor_h_[i]);
      in.get(last_used_[i]);
      predictors_[i].load(in, p_);
    }
  }
  void setStrategy(MatrixLegendreStrategy strategy) {
    if (strategy == MatrixLegendreStrategy::kExternal && !external_) {
      throw InvalidArgument("strategy = external is invalid: set a solver by setExternalSolver");
    }
    strategy_ = strategy;
  }

  /// A solver of DDB's Cayley equation r(p) = (I + a(p)) p (I − a(p)) − W = 0 from outside the
  /// matrix-free iterations, for cross-checks (Ceres: matrix_legendre_ceres.h). Called with
  /// this solver, W and h, it starts from iterate(), may call residualInto and jacobianTimes,
  /// leaves its solution in iterate() and returns the iterations it took; the solve then
  /// checks the residual as Newton's. Sets the strategy kExternal.
  using ExternalSolver = std::function<int(MatrixLegendreSolver& solver, const Dual& W, double h)>;
  void setExternalSolver(ExternalSolver solver) {
    external_ = std::move(solver);
    strategy_ = MatrixLegendreStrategy::kExternal;
  }
  /// The iterate p of the solve in progress (an external solver's unknown).
  Dual& iterate() { return p_; }
  /// out = r(p) = (I + a) p (I − a) − W at p = iterate(), a = a(p) (Cayley).
  void residualInto(const Dual& W, double h, Dual& out) {
    static_assert(kProductForm, "the external solvers solve the Cayley equation");
    updateVelocity(h);
    G::cayleyFixedPoint(W, a_, p_, ap_, apa_, next_);
    B::sum(1.0, p_, -1.0, next_, out);
  }
  /// out = Dr(p)[v] at the p of the last residualInto (v and out are the caller's).
  void jacobianTimes(const Dual& v, double h, Dual& out) {
    halfStepDerivative(v, h, delta_a_);
    G::cayleyLinearised(a_, p_, v, delta_a_, t1_, t2_, out);
  }

  /// Solves (I + hξ(p)/2) p (I − hξ(p)/2) = target(ξ, p); returns ξ and sets p.
  template <class Target>
  Algebra solve(const Target& target, const Dual& near, double t, double h, Dual& p) {
    solveInPlace(target, near, t, h);
    p = p_;
    return xi_;
  }

  /// DDB's equation: target = the momentum M_k.
  Algebra solve(const Dual& momentum, double t, double h, Dual& p) {
    return solve(FixedMomentum<G, Dual>{momentum}, momentum, t, h, p);
  }

  /// Solves without copying out: the solution is solution(), ξ = velocity() and
  /// a = hξ/2 = halfStep(), valid until the next solve. For DDB's target (the momentum M)
  /// it also leaves the product a p = halfStepTimesSolution() and certifies, when it can,
  /// frozenSolution(): p̃ = (I + a)⁻¹ M (I − a)⁻¹ for this a to rounding, with which the
  /// update Ad*_{cay(2a)} M = M − 2[a, p̃] costs one product (matrix_cayley_transport.h).
  /// A target that moves with p is evaluated after ξ(p), a = hξ/2 and (Cayley) a p =
  /// halfStepTimesSolution() of that p. target() is its value W at the solution, and (Cayley)
  /// frozenSolution() solves (I + a) p̃ (I − a) = W when certified; with the exponential,
  /// eigenbasis() is ξ's.
  template <class Target>
  void solveInPlace(const Target& target, const Dual& near, double t, double h) {
    constexpr bool kFixed = std::is_same_v<Target, FixedMomentum<G, Dual>>;
    allocate(near);
    CorrectionPredictor<Dual>& predictor = predictorFor(h);
    stats_ = LegendreStats{};
    frozen_exact_ = false;
    const auto targetValue = [&]() -> const Dual& {
      if constexpr (kFixed) {
        return target.momentum;
      } else {
        target.evaluateInto(xi_, p_, target_);
        return target_;
      }
    };
    predictor.predict(near, p_);
    const double scale = B::frobeniusNorm(near);
    const double tolerance = options_.relative_tolerance * scale;
    double previous = INFINITY;
    bool converged = false;
    const bool forced = strategy_ == MatrixLegendreStrategy::kFixedPoint;
    const bool fixed_point = strategy_ == MatrixLegendreStrategy::kAuto || forced;
    // Without a Newton fallback (the exponential) the sweeps go on while they contract.
    const int budget = (forced || !kFixed || !kProductForm) ? kMaxForcedFixedPoint : kMaxFixedPoint;
    int extra = 0;  // sweeps past the tolerance, for a certified frozen solution
    anderson_.reset();
    double smallest = INFINITY;  // the smallest update of a moving target's sweeps, and when
    int smallest_at = 0;
    for (int k = 0; fixed_point && k < budget; ++k) {
      updateVelocity(h);
      if constexpr (kProductForm) B::multiply(a_, p_, ap_);  // before the target, which may use it
      const Dual& W = targetValue();
      sweep(W, h);
      const double update = B::frobeniusDistance(next_, p_);
      ++stats_.fixed_point;
      if (!std::isfinite(update)) {
        stats_.residual = update;
        break;
      }
      // A contraction of rate ρ leaves the iterate p an error of at most update/(1 − ρ)
      // and the next one ρ/(1 − ρ)·update; ρ is measured from the last two updates (on a
      // first sweep it is the last solve's: the rate belongs to the map near the solution
      // and moves with the state, docs/design/architecture.md).
      if constexpr (kFixed) {
        const double rate = std::isfinite(previous) ? update / previous : rate_;
        // DDB's update uses a = a(p) of this iterate p, so p itself must be within the
        // tolerance; the next iterate then serves the exact update (frozenSolution).
        if (std::isfinite(previous)) rate_ = rate;
        const bool contracting = rate < kSlowContraction;
        const double error = contracting ? update / (1.0 - rate) : update;
        stats_.residual = error;
        // A sweep stalled at rounding level is not contracting: Cayley hands it to Newton,
        // whose first check accepts a residual within the tolerance; the exponential, which
        // has no Newton step, applies that check here (its error is then the update, p's
        // residual).
        if ((contracting || !kProductForm) && error <= tolerance) {
          converged = true;
          if (!kProductForm || certifyFrozenSolution(W, update, scale) ||
              extra++ == kMaxExtraSweeps) {
            break;
          }
        } else if (!forced && k >= 2 &&
                   update > (kProductForm ? kSlowContraction : 1.0) * previous) {
          break;  // contracting too slowly: Newton–Krylov takes over (exp: not contracting)
        }
      } else {
        // Other targets move with p. The accepted iterate is p itself, whose ξ, a, target
        // and (exp) eigenbasis are at hand for the step (target()), and its residual is the
        // update, the measure Newton accepts on. The sweeps are mixed (Anderson), which
        // removes the slowly contracting directions a plain sweep leaves
        // (docs/design/architecture.md, "The symmetric DDB's fixed point").
        stats_.residual = update;
        if (update <= tolerance) {
          converged = true;
          if constexpr (kProductForm) certifyFrozenSolution(target_, update, scale);
          break;
        }
        // Mixed residuals need not fall every sweep, but kStallSweeps without a new smallest
        // one is a solve stalled (at rounding above the tolerance, or diverging): it fails
        // now instead of after the whole budget.
        if (update < smallest) {
          smallest = update;
          smallest_at = k;
        } else if (k - smallest_at >= kStallSweeps) {
          break;
        }
        anderson_.mix(p_, next_);
        previous = update;
        p_.swap(next_);
        continue;
      }
      previous = update;
      p_.swap(next_);
    }
    if constexpr (!kProductForm) {
      if (strategy_ != MatrixLegendreStrategy::kAuto && !forced) {
        throw InvalidArgument(std::string("strategy is invalid: the ") + R::kName +
                              " retraction is solved by the fixed point only");
      }
    } else if constexpr (kFixed) {
      const bool newton = strategy_ == MatrixLegendreStrategy::kNewtonKrylov ||
                          (strategy_ == MatrixLegendreStrategy::kAuto && !converged);
      const bool external = strategy_ == MatrixLegendreStrategy::kExternal;
      if (newton) converged = newtonKrylov(target.momentum, h, tolerance);
      if (external) converged = externalSolve(target.momentum, h, tolerance);
      // Both end on a sweep at their solution p: a, a p and the next iterate are at hand.
      if (converged && (newton || external)) {
        certifyFrozenSolution(target.momentum, B::frobeniusDistance(next_, p_), scale);
      }
    } else if (strategy_ != MatrixLegendreStrategy::kAuto && !forced) {
      throw InvalidArgument(
          "strategy is invalid: only the fixed point solves a target that depends on p");
    }
    if (!converged && !std::isfinite(stats_.residual)) {
      // Overflow (e.g. |α| or h near the double range) is not a missed tolerance.
      throw NonFiniteState("discrete Legendre equation (matrix-free)", -1, t, h, B::describe(p_),
                           "iterate");
    }
    if (!converged) {
      throw SolveFailure(std::string("discrete Legendre equation (matrix-free, ") +
                             (stats_.newton > 0 ? "Newton" : "fixed point") + ")",
                         -1, t, h, stats_.residual, tolerance);
    }
    if constexpr (!kProductForm) checkInjectivity(t, h, kEigenbasisSweep);
    // The most accurate solution at hand: p̃ when certified (it solves the frozen-a equation
    // to rounding), else the next iterate.
    predictor.remember(!kFixed ? p_ : frozen_exact_ ? frozen_ : next_, near);
  }

  const Dual& solution() const { return p_; }
  /// The target's value at solution(), after a solve of a target that moves with p.
  const Dual& target() const { return target_; }
  const Algebra& velocity() const { return xi_; }
  const Algebra& halfStep() const { return a_; }
  /// a p, after a solve of DDB's target.
  const Dual& halfStepTimesSolution() const { return ap_; }
  /// p̃ with (I + a) p̃ (I − a) = M to rounding (see solveInPlace), or nullptr when the
  /// last solve could not certify it (the update then forms cay(2a)).
  const Dual* frozenSolution() const { return frozen_exact_ ? &frozen_ : nullptr; }
  /// The exponential: the eigenbasis of ξ = velocity() after a solve.
  auto& eigenbasis() { return eigenbasis_; }

 private:
  /// Sweeps past the tolerance, at most, to certify the frozen solution.
  static constexpr int kMaxExtraSweeps = 2;

  void allocate(const Dual& like) {
    if (B::sameShape(p_, like)) return;
    for (Dual* m : {&p_, &next_, &xi_, &a_, &ap_, &apa_, &frozen_, &residual_, &delta_, &delta_a_,
                    &t1_, &t2_, &target_, &argument_, &direction_}) {
      B::zeroLike(*m, like);
    }
    forgetPredictions();
  }

  // Corrections scale with h, so only same-h ones extrapolate: one predictor per step size,
  // enough for the distinct sub-steps of a composition (a triple jump has two, Yoshida's
  // seven stages four), each reused the next time its h comes; the least recently used
  // one is replaced by a new h.
  CorrectionPredictor<Dual>& predictorFor(double h) {
    std::size_t slot = 0;
    for (std::size_t i = 0; i < kPredictors; ++i) {
      if (predictor_h_[i] == h) {
        slot = i;
        break;
      }
      if (last_used_[i] < last_used_[slot]) slot = i;
    }
    if (predictor_h_[slot] != h) {
      predictors_[slot].reset();
      predictor_h_[slot] = h;
    }
    last_used_[slot] = ++clock_;
    return predictors_[slot];
  }
  void forgetPredictions() {
    for (auto& predictor : predictors_) predictor.reset();
    predictor_h_.fill(NAN);
    last_used_.fill(0);
  }

  // With a = a(p) frozen, (I + a) p̃ (I − a) = M is linear in p̃, next = M − [a, p] + a p a
  // is its fixed-point map, and Ad*_{cay(2a)} M = M − 2[a, p̃] exactly. M − 2[a, q] misses it by
  // 2‖[a, p̃ − q]‖, which must stay below rounding, u‖M‖. q is the next iterate or, one product
  // more, the frozen sweep after it with a p a kept from p (it changes by a(next − p)a); the
  // group bounds both misses (SkewHermitianGroup::cayleyFrozenErrors; over the dual numbers
  // DualNumberSUNOn's, which uses that the ε-part does not feed back into the 1-part). Returns
  // whether frozen_ now holds a certified p̃.
  bool certifyFrozenSolution(const Dual& M, double update, double scale) {
    const double rounding = 0.5 * std::numeric_limits<double>::epsilon() * scale;
    frozen_exact_ = false;
    double next_error = INFINITY, refined_error = INFINITY;
    G::cayleyFrozenErrors(a_, p_, next_, update, next_error, refined_error);
    if (next_error <= rounding) {
      frozen_.swap(next_);
      return frozen_exact_ = true;
    }
    if (refined_error > rounding) return false;
    B::multiply(a_, next_, t1_);  // frozen_ = M − [a, next] + a p a
    B::sum(1.0, M, -1.0, t1_, 1.0, apa_, frozen_);
    B::addAdjoint(1.0, t1_, frozen_);
    ++stats_.refinements;
    return frozen_exact_ = true;
  }

  // One sweep p ← F(p) (into next_) of a fixed point of target = (dτ⁻¹_{hξ(p)})* p, after
  // updateVelocity (and for Cayley ap_ = a p):
  //   Cayley: F(p) = W − [a, p] + a p a = p − r(p), r(p) = (I + a)p(I − a) − W;
  //   exp: F(p) = ((dexp⁻¹_{hξ})*)⁻¹ W, which multiplies entry (a, b) of ξ's eigenbasis by
  //     (e^{−iδ} − 1)/(−iδ), δ = h(θ_a − θ_b) (skew_hermitian_eigenbasis.h): p enters through
  //     ξ only, so the sweep contracts at the rate of that dependence alone;
  //   exp, series cut after ad^order (the paper's ddb-exp): F(p) = p − r(p) with
  //     r(p) = Σ_{j≤order} B_j/j! (ad*_{hξ})^j p − W, ad*_x μ = [μ, x] = μx − (μx)ᴴ.
  void sweep(const Dual& W, double h) {
    if constexpr (kProductForm) {
      G::cayleyFixedPointGiven(W, a_, ap_, apa_, next_);
    } else if constexpr (kEigenbasisSweep) {
      if (!eigenbasis_.compute(xi_)) {
        B::scale(NAN, W, next_);  // ξ not finite: the update shows it
        return;
      }
      eigenbasis_.apply(PhaseFunction::kInverseDexpInverseDual, h, W, next_);
    } else {
      B::copy(W, next_);
      B::copy(p_, delta_);
      for (int j = 1; j <= retraction_.order(); ++j) {
        B::multiply(delta_, a_, t1_);  // ad*_{hξ} = 2 ad*_a
        B::scale(2.0, t1_, delta_);    // 2(t1 − t1ᴴ), exactly as 2·t1 − 2·t1ᴴ
        B::addAdjoint(-2.0, t1_, delta_);
        B::axpy(-bernoulliOverFactorial(j), delta_, next_);
      }
    }
  }

  // The exponential's injectivity limit (integrators/solvers/injectivity_guard.h): a solution with
  // h·adRadius(ξ) ≥ π lies on another branch; refused as on SO(3). The eigenbasis of ξ is
  // current after a DDB solve with the closed form, recomputed otherwise.
  void checkInjectivity(double t, double h, bool basis_current) {
    if (!basis_current && !eigenbasis_.compute(xi_)) {
      throw NonFiniteState("discrete Legendre equation (matrix-free)", -1, t, h, B::describe(xi_),
                           "velocity");
    }
    const double norm = h * eigenbasis_.adRadius();
    if (norm >= InjectivityGuard<R>::kLimit) {
      throw InjectivityLimit(std::string("DDB with the ") + R::kName + " retraction", norm,
                             InjectivityGuard<R>::kLimit,
                             InjectivityGuard<R>::kLimit / eigenbasis_.adRadius(), -1, t, h);
    }
  }

  // ξ = ∂H/∂μ(p) as the system evaluates it (at the algebra part of p, projected onto the
  // algebra: LiePoissonSystem::velocityInto), a = hξ/2.
  void updateVelocity(double h) {
    system_.velocityInto(p_, argument_, xi_);
    B::scale(0.5 * h, xi_, a_);
  }

  // δa = (h/2) Dξ(p)[v] at the p of the last updateVelocity.
  void halfStepDerivative(const Dual& v, double h, Dual& out) {
    system_.velocityDerivativeInto(argument_, v, direction_, out);
    B::scale(0.5 * h, out, out);
  }

  // Newton on r(p) = (I + a)p(I − a) − W with GMRES on J δ = −r.
  bool newtonKrylov(const Dual& W, double h, double tolerance) {
    gmres_.resize(W);  // its basis only when Newton–Krylov is needed
    for (int k = 0; k < kMaxNewton; ++k) {
      updateVelocity(h);
      G::cayleyFixedPoint(W, a_, p_, ap_, apa_, next_);
      B::sum(1.0, next_, -1.0, p_, residual_);  // −r(p)
      stats_.residual = B::frobeniusNorm(residual_);
      if (!std::isfinite(stats_.residual)) return false;
      if (stats_.residual <= tolerance) return true;
      ++stats_.newton;
      B::setZero(delta_);
      const auto jacobian = [&](const Dual& v, Dual& out) {
        halfStepDerivative(v, h, delta_a_);
        G::cayleyLinearised(a_, p_, v, delta_a_, t1_, t2_, out);
      };
      // Inexact Newton: GMRES to 1e-4 of the current residual (never below a tenth of
      // the final tolerance), which keeps the outer convergence quadratic in practice.
      const double forcing = std::max(0.1 * tolerance, 1e-4 * stats_.residual);
      const auto krylov = gmres_.solve(jacobian, residual_, delta_, forcing, kMaxKrylov);
      stats_.krylov += krylov.iterations;
      B::axpy(1.0, delta_, p_);
    }
    updateVelocity(h);
    G::cayleyFixedPoint(W, a_, p_, ap_, apa_, next_);
    stats_.residual = B::frobeniusDistance(p_, next_);
    return stats_.residual <= tolerance;
  }

  bool externalSolve(const Dual& W, double h, double tolerance) {
    stats_.newton += external_(*this, W, h);
    updateVelocity(h);
    G::cayleyFixedPoint(W, a_, p_, ap_, apa_, next_);
    stats_.residual = B::frobeniusDistance(p_, next_);
    return stats_.residual <= tolerance;
  }

  const System& system_;
  const R& retraction_;
  LegendreForm form_;
  SolverOptions options_;
  static constexpr std::size_t kPredictors = 4;
  std::array<CorrectionPredictor<Dual>, kPredictors> predictors_;
  std::array<double, kPredictors> predictor_h_{NAN, NAN, NAN, NAN};  // their step sizes
  std::array<long, kPredictors> last_used_{};
  long clock_ = 0;
  AndersonAcceleration<Dual> anderson_;
  double rate_ = NAN;  // the contraction rate last measured
  bool frozen_exact_ = false;
  MatrixLegendreStrategy strategy_ = MatrixLegendreStrategy::kAuto;
  ExternalSolver external_;
  LegendreStats stats_;
  Dual p_, next_, xi_, a_, ap_, apa_, frozen_, residual_, delta_, delta_a_, t1_, t2_, target_;
  Dual argument_, direction_;  // the algebra parts of p and of a Newton direction

  MatrixFreeGmres<Dual> gmres_;
  // ξ's eigenbasis, for the exponential's sweeps only: the Cayley map's product form needs none,
  // so a backend without the spectral calculus runs it (core/dual_matrix.h).
  typename detail::EigenbasisSlot<B, !kProductForm>::type eigenbasis_;
};

}  // namespace ddb
