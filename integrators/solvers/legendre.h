// The solver of the discrete Legendre transform of a DDB step for small fixed-size groups
// (paper, Section 4.1):
//   (dτ^{-1}_{hξ})* p = target(ξ, p),  p = ∂l/∂ξ(ξ)  (Lagrangian form, unknown ξ)
//                                      ξ = ∂H/∂μ(p)  (Hamiltonian form, unknown p)
// DDB's target is the momentum M_k; the symmetric variants' targets depend on the unknown.
// Two stages (docs/reference/conventions.md §4), as the matrix-free solver's (matrix_legendre.h):
//   predictor: p = near + c, the correction c = p − near extrapolated from the last solves at
//     the same h (and, in a composition, the same stage: slotFor) by the polynomial whose degree
//     predicted the last solve best (up to kPredictorOrder − 1; PolynomialPredictor), then
//     fixed-point sweeps p ← p − r(p), one residual evaluation each. Their rate ‖I − ∂r/∂p‖ is O(h)
//     (0.02–0.03 on Scenario A at h = 0.1): while it is at most kFastContraction they go on to the
//     tolerance, cheaper than the one Newton iteration that would replace the last few
//     (docs/design/architecture.md); slower, they stop within √tolerance, from where one Newton
//     step squares the residual to the tolerance;
//   corrector, when the sweeps have not converged: Levenberg–Marquardt (TinyLevenbergMarquardt)
//     on LegendreEquation's analytic Jacobian, to the relative tolerance: first with the
//     Jacobian of the predicted guess kept (runChordIterations: one Jacobian per solve),
//     then, if that has not converged within kChordIterations, with a fresh Jacobian per
//     iterate; the typed SolveFailure when the tolerance is not reached.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/detail/tiny_solver.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/solvers/injectivity_guard.h>
#include <ddb/integrators/solvers/legendre_equation.h>
#include <ddb/integrators/solvers/legendre_stats.h>
#include <ddb/integrators/solvers/polynomial_predictor.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <string>

namespace ddb {

template <class R>
class DiscreteLegendreSolver {
 public:
  using G = typename R::Group;
  static constexpr int kDim = G::kDim;
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;
  using Vector = Eigen::Matrix<double, kDim, 1>;
  /// A measured rate at or below this is fast: the sweeps go on to the tolerance.
  static constexpr double kFastContraction = 0.1;
  /// A sweep that shrinks the update by less than this hands over to Newton at once.
  static constexpr double kSlowContraction = 0.5;
  /// Iterations with the Jacobian of the predicted guess before fresh Jacobians take over.
  static constexpr int kChordIterations = 3;
  /// The most corrections the predictor's extrapolation combines (its degree + 1): on
  /// Scenario A at h = 0.1 the sweeps a step fall from 6.2 at 3 (quadratic) to 3.3 at 8; 10
  /// and 12 save a few nanoseconds more for a larger record (docs/results/benchmarks.md, "The
  /// small Legendre solver's predictor"). The matrix solver's predictor stops at 8 too.
  static constexpr int kPredictorOrder = 8;

  DiscreteLegendreSolver(const LiePoissonSystem<G>& system, const R& retraction, LegendreForm form,
                         SolverOptions options)
      : system_(system),
        retraction_(retraction),
        form_(form),
        options_(options),
        max_sweeps_(system.hamiltonian().gradientIsASolve() ? 0 : options.max_sweeps) {
    if (form_ == LegendreForm::kLagrangian && system_.lagrangian() == nullptr) {
      throw InvalidArgument("form = lagrangian is invalid: system '" + system_.name() +
                            "' has no Lagrangian (use the Hamiltonian form)");
    }
  }

  /// Forgets the corrections of earlier solves (a new trajectory).
  void reset() {
    for (Slot& slot : slots_) slot = Slot{};
    previous_h_ = 0.0;
    solves_ = 0;
  }
  LegendreForm form() const { return form_; }
  /// The warm start (OneStepMethod::saveWarmStart): the step size of the last solve, the
  /// number of solves, and each slot's key, contraction and corrections.
  void saveWarmStart(BinaryRecordWriter& out) const {
    out.tag(kRecordTag);
    out.put(previous_h_);
    out.put(solves_);
    for (const Slot& slot : slots_) {
      out.put(slot.h);
      out.put(slot.previous_h);
      out.put(slot.squared_rate);
      out.put(slot.last_solve);
      slot.predictor.save(out);
    }
  }
  /// As loadWarmStart(in): a small group's record does not depend on the state (the matrix
  /// solver's signature, so that a method loads either solver's alike).
  void loadWarmStart(BinaryRecordReader& in, const Dual&) { loadWarmStart(in); }
  /// Reads saveWarmStart's record, or that of 0.2.0 (the last three corrections at one h,
  /// extrapolated quadratically), whose corrections a slot for that h restarts from.
  void loadWarmStart(BinaryRecordReader& in) {
    reset();
    const std::string tag = in.get<std::string>();
    if (tag == kRecordTagOf020) {
      const int count = in.get<int>();
      if (count < 0 || count > 3) throw CorruptRecord("a correction count outside 0..3");
      Slot& slot = slots_[0];
      in.get(slot.squared_rate);
      in.get(slot.h);
      std::array<Dual, 3> corrections;  // newest first
      for (Dual& c : corrections) in.get(c);
      slot.predictor.restart(corrections, count);
      slot.previous_h = previous_h_ = slot.h;
      return;
    }
    if (tag != kRecordTag) {
      throw CorruptRecord("expected part '" + std::string(kRecordTag) + "', found '" + tag + "'");
    }
    in.get(previous_h_);
    in.get(solves_);
    for (Slot& slot : slots_) {
      in.get(slot.h);
      in.get(slot.previous_h);
      in.get(slot.squared_rate);
      in.get(slot.last_solve);
      slot.predictor.load(in);
    }
  }
  /// Sweeps, Newton iterations and final residual of the last solve.
  const LegendreStats& stats() const { return stats_; }

  /// Solves (dτ^{-1}_{hξ})* p = target(ξ, p); returns ξ and sets p. `near` is a momentum
  /// close to the solution (the target at the start of the step), whose norm scales the
  /// relative tolerance.
  template <class Target>
  Algebra solve(const Target& target, const Dual& near, double t, double h, Dual& p) {
    solveOutOfLine(target, near, t, h);
    p = p_;
    return xi_;
  }

  /// Solves without copying out: the solution p is solution(), ξ = velocity(), valid until the
  /// next solve (MatrixLegendreSolver's interface, which the DDB steps use on every group).
  /// Always inlined into the step that calls it: out of line, a rigid-body ddb-cay step took
  /// 109-112 ns against 101 ns, the same bits (docs/results/benchmarks.md, "The small
  /// Legendre solve inlined into its step").
  template <class Target>
  EIGEN_ALWAYS_INLINE void solveInPlace(const Target& target, const Dual& near, double t,
                                        double h) {
    // The solve on locals, which stay in registers (members would be reloaded around every
    // evaluation of the target, which may refer to any memory), copied out at the end.
    Dual p;
    Algebra xi;
    InjectivityGuard<R>::beforeSolve(system_, near, t, h);
    const LegendreEquation<R, Target> equation{system_, retraction_, target, h, form_};
    Slot& slot = slotFor(h);
    Dual guess = slot.predictor.predict(near);
    stats_ = LegendreStats{};
    const double scale = near.norm();
    double squared_rate = slot.squared_rate;  // a local, as p and ξ
    const bool swept = sweep(equation, scale, squared_rate, guess);
    slot.squared_rate = squared_rate;
    if (swept) {
      p = guess;
      xi = system_.velocity(p);
    } else {
      unknown_ = form_ == LegendreForm::kLagrangian ? Vector(system_.velocity(guess)) : guess;
      TinySolveStats solved = runChordIterations(
          equation, unknown_, options_.relative_tolerance * scale, kChordIterations);
      stats_.newton = solved.iterations;
      if (!solved.converged) {  // from where the chord iterations left it, with fresh Jacobians
        solved =
            solveTinyWith(equation, unknown_, scale, options_, "discrete Legendre equation", t, h);
        stats_.newton += solved.iterations;
      }
      stats_.residual = solved.residual;
      equation.unpack(unknown_.data(), xi, p);
    }
    InjectivityGuard<R>::afterSolve(system_, near, xi, t, h);
    slot.predictor.remember(p - near);
    p_ = p;
    xi_ = xi;
  }

  const Dual& solution() const { return p_; }
  const Algebra& velocity() const { return xi_; }
  /// The retraction τ the equation is written in.
  const R& retraction() const { return retraction_; }

  /// DDB's equation M = (dτ^{-1}_{hξ})* ∂l/∂ξ(ξ).
  Algebra solve(const Dual& momentum, double t, double h, Dual& p) {
    return solve(FixedMomentum<G>{momentum}, momentum, t, h, p);
  }

 private:
  // Fixed-point sweeps p ← p − r(p) from `p`, the residual r measured at every iterate.
  // Returns true when an iterate's ‖r‖ met the tolerance: p is then the next iterate, closer
  // by the contraction rate, if that rate is known to be below kSlowContraction, else the
  // iterate itself (stats_.residual is the measured ‖r‖ of that iterate). Returns false for
  // Newton to go on from p:
  //   - at once when a sweep grew or is not finite (it is not applied) or shrank by less
  //     than kSlowContraction;
  //   - with a rate above kFastContraction, once the residual left, about rate · ‖update‖, is
  //     within √tolerance, where one chord Newton iteration squares it to the tolerance;
  //   - after max_sweeps_: SolverOptions::max_sweeps, or 0 when ∂H/∂μ is itself a solve
  //     (a sweep then costs about as much as a Newton step; docs/design/architecture.md, "Small
  //     Legendre solves", has both measurements).
  // The rate is the ratio of the last two updates; on the first sweep, the last solve's in
  // the same slot (it belongs to the map near the solution and moves slowly with the state);
  // 1, i.e. slow, until measured.
  template <class Equation>
  bool sweep(const Equation& equation, double scale, double& squared_rate, Dual& p) {
    // Squared norms and rates: no square root waits in the loop (docs/design/architecture.md). The
    // decisions are those on norms, up to ties (Eigen's norm() is √squaredNorm() too).
    const double tolerance = square(options_.relative_tolerance * scale);
    const double newton_ready = options_.relative_tolerance * square(scale);
    double last = INFINITY;
    for (int k = 0; k < max_sweeps_; ++k) {
      const Dual update = equation.residualAtMomentum(p);
      const double size = update.squaredNorm();
      if (!std::isfinite(size) || size > last) {  // keep p as it is
        stats_.residual = std::sqrt(size);
        squared_rate = 1.0;
        return false;
      }
      if (k > 0) squared_rate = size / last;
      ++stats_.fixed_point;
      if (size <= tolerance) {
        stats_.residual = std::sqrt(size);
        if (squared_rate <= square(kSlowContraction)) p -= update;
        return true;
      }
      p -= update;
      if ((k > 0 && squared_rate > square(kSlowContraction)) ||
          (squared_rate > square(kFastContraction) && squared_rate * size <= newton_ready)) {
        stats_.residual = std::sqrt(size);
        return false;
      }
      last = size;
    }
    if (max_sweeps_ > 0) stats_.residual = std::sqrt(last);
    return false;
  }
  static constexpr double square(double x) { return x * x; }

  // solve()'s call of the solve, kept out of line: inlined into solve() (the paper's symmetric
  // DDB solves through it), a rigid-body sddb-paper-cay step took 1.6 % longer, the same bits
  // (docs/results/benchmarks.md, "The small Legendre solve inlined into its step").
  template <class Target>
  EIGEN_DONT_INLINE void solveOutOfLine(const Target& target, const Dual& near, double t,
                                        double h) {
    solveInPlace(target, near, t, h);
  }

  // Corrections and rates scale with h, and a composition's stages (Φ_{γ₁h} ∘ Φ_{γ₂h} ∘ …)
  // each follow their own smooth sequence, interleaved: a slot of corrections per stage, which
  // the pair (h, the previous solve's h) tells apart for the compositions of the method table
  // (the triple jump's (γ₁h, γ₁h), (γ₂h, γ₁h), (γ₁h, γ₂h)); a run at one h uses one slot
  // throughout, the first solve after reset() included. A slot unused for kSlots solves is
  // stale (a step size an adaptive run left and came back to): it starts afresh.
  struct Slot {
    double h = 0.0, previous_h = 0.0;  // its key; 0: free
    double squared_rate = 1.0;         // the contraction of its last two sweeps, squared; 1 (slow)
                                       // until measured
    long last_solve = -1;              // the solve that last used it
    PolynomialPredictor<Dual, kPredictorOrder> predictor;
  };
  static constexpr int kSlots = 8;  // Yoshida's order-6 composition has 7 stages

  Slot& slotFor(double h) {
    const double previous = previous_h_ == 0.0 ? h : previous_h_;
    previous_h_ = h;
    const long solve = solves_++;
    Slot* oldest = &slots_[0];
    for (Slot& slot : slots_) {
      if (slot.h == h && slot.previous_h == previous && solve - slot.last_solve <= kSlots) {
        slot.last_solve = solve;
        return slot;
      }
      if (slot.last_solve < oldest->last_solve) oldest = &slot;
    }
    *oldest = Slot{h, previous, 1.0, solve, {}};
    return *oldest;
  }

  static constexpr const char* kRecordTag = "discrete legendre solver, polynomial predictor";
  static constexpr const char* kRecordTagOf020 = "discrete legendre solver";

  const LiePoissonSystem<G>& system_;
  const R& retraction_;
  LegendreForm form_;
  SolverOptions options_;
  int max_sweeps_;
  LegendreStats stats_;
  std::array<Slot, kSlots> slots_;
  double previous_h_ = 0.0;  // the h of the last solve; 0 before the first
  long solves_ = 0;          // solves since reset()
  Vector unknown_ = Vector::Zero();
  Dual p_ = Dual::Zero();         // the last solve's solution
  Algebra xi_ = Algebra::Zero();  // and its ξ
};

}  // namespace ddb
