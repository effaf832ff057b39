// Symmetric second-order DDB variants (paper, remark after the retraction formulas;
// docs/reference/conventions.md §2).
//
// SymmetricDdb, the one-step symmetric DDB: solve
//   (dτ^{-1}_{hξ})* ∂l/∂ξ(ξ) = Ad*_{τ(hφ(ξ)/2)} μ_k,
// then μ_{k+1} = Ad*_{τ(hφ/2) τ(hξ) τ(hφ/2)} μ_k. It satisfies Φ_{-h} = Φ_h^{-1}, so
// it is second order and symmetric compositions raise its order, every stage on the
// coadjoint orbit.
//
// PaperSymmetricDdb, the paper's variant as written: ξ_{k+1} is coupled to ξ_k by
//   (dτ^{-1}_{hξ_{k+1}})* ∂l(ξ_{k+1}) = Ad*_{φ_d} (dτ^{-1}_{-hξ_k})* ∂l(ξ_k)
// with φ_d = τ(hφ((ξ_k+ξ_{k+1})/2)) (midpoint) or τ(h/2 φ(ξ_k) + h/2 φ(ξ_{k+1}))
// (trapezoidal), and M_k = (dτ^{-1}_{hξ_k})* ∂l(ξ_k) is the output. Measured first
// order in M: the Legendre equation pairs M_k (time t_k) with ξ_k (t_k + h/2) and
// ignores the dissipation over that half step. ReadOut::kHalfForce is the fix of
// docs/reference/conventions.md §2: start from (dτ^{-1}_{hξ₀})* ∂l(ξ₀) = Ad*_{τ(hφ(ξ₀)/2)} μ₀ and
// read out μ_k = Ad*_{τ(-hφ(ξ_k)/2)} M_k; it is second order and still exactly on the orbit.
#pragma once

#include <ddb/core/detail/jet_jacobian.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/integrators/matrix_kernels/matrix_retraction.h>
#include <ddb/integrators/methods/legendre_method.h>

#include <memory>
#include <string>
#include <type_traits>

namespace ddb {

/// Ad*_{τ(hφ(ξ)/2)} μ: the half-force target of the symmetric Legendre equations.
template <class R>
struct HalfForceTarget {
  using G = typename R::Group;
  const LiePoissonSystem<G>& system;
  const R& retraction;
  const typename G::template Dual<double>& mu;
  double h;
  template <class A, class D>
  D operator()(const A& xi, const D& p) const {
    using T = typename D::Scalar;
    const A half = system.dissipation(xi, p) * T(0.5 * h);
    return G::AdDual(retraction.tau(half), D(mu.template cast<T>()));
  }
  /// d/du of the target through ξ(u), p(u) (LegendreEquation), by Jets.
  template <class Xi, class P>
  Xi jacobian(const typename G::template Algebra<double>& xi,
              const typename G::template Dual<double>& p, const Xi& dxi, const P& dp) const {
    return jacobianByJets<G::kDim>(*this, xi, dxi, p, dp);
  }
};

/// SymmetricDdb's update on the small groups: the half-force target (HalfForceTarget, by Jets
/// in the solve) and μ ← Ad*_{τ(hφ/2) τ(hξ) τ(hφ/2)} μ through the group's product.
template <class R>
class FixedSizeSymmetricUpdate {
 public:
  using G = typename R::Group;
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;

  void resize(const Dual&) {}
  template <class Solver>
  HalfForceTarget<R> target(const LiePoissonSystem<G>& system, const R& retraction, const Solver&,
                            const Dual& mu, double h) {
    return {system, retraction, mu, h};
  }
  template <class Solver>
  void apply(const LiePoissonSystem<G>& system, const R& retraction, Solver& solver, double h,
             Dual& mu) {
    const Algebra half = (0.5 * h) * system.dissipation(solver.velocity(), solver.solution());
    const Algebra hxi = h * solver.velocity();
    const auto kick = retraction.tau(half);
    mu = G::AdDual(G::compose(G::compose(kick, retraction.tau(hxi)), kick), mu);
  }
};

/// SymmetricDdb's update on matrix groups (any backend): each factor of
/// Ad*_{τ(hφ/2) τ(hξ) τ(hφ/2)} applied as an increment (matrix_conjugation.h), with
/// preallocated workspaces. The solver accepts the p at which it evaluated the target last, so
/// the first factor applied to μ is the target's value, the kick is still prepared at that p's
/// φ, and the middle factor uses what the solve left: the frozen solution (Cayley, one product)
/// or ξ's eigenbasis (exp).
template <class R>
class MatrixSymmetricUpdate {
 public:
  using G = typename R::Group;
  using Dual = typename G::template Dual<double>;
  using B = MatrixBackend<Dual>;

  /// The matrices of mu's shape (and layout); nothing if they have it already.
  void resize(const Dual& mu) {
    if (B::sameShape(product_, mu)) return;
    for (Dual* m : {&product_, &commutator_, &half_, &drift_}) B::zeroLike(*m, mu);
  }

  /// The half-force target Ad*_{τ(hφ(ξ, p)/2)} μ, written into the solver's workspace; the
  /// kick stays prepared at this p's φ.
  template <class Solver>
  struct Target {
    MatrixSymmetricUpdate& update;
    const LiePoissonSystem<G>& system;
    const Solver& solver;
    const Dual& mu;
    double h;
    void evaluateInto(const Dual& xi, const Dual& p, Dual& out) const {
      MatrixSymmetricUpdate& w = update;
      if constexpr (MatrixRetraction<R>::kSweep == MatrixSweep::kProductForm) {
        // The solver's a p of this p: no product.
        system.halfStepDissipationInto(solver.halfStepTimesSolution(), w.commutator_, w.half_);
      } else {
        system.dissipationInto(p, xi, 0.5 * h, w.product_, w.commutator_, w.half_);
      }
      B::copy(mu, out);
      w.kick_.prepare(w.half_);
      w.kick_.apply(out);
    }
  };
  template <class Solver>
  Target<Solver> target(const LiePoissonSystem<G>& system, const R&, const Solver& solver,
                        const Dual& mu, double h) {
    return {*this, system, solver, mu, h};
  }

  template <class Solver>
  void apply(const LiePoissonSystem<G>&, const R&, Solver& solver, double h, Dual& mu) {
    B::copy(solver.target(), mu);
    if (!MatrixRetraction<R>::applySolvedFlow(solver, h, flow_, mu)) {
      B::scale(h, solver.velocity(), drift_);  // μ ← Ad*_{τ(hξ)} μ, τ(hξ) formed from ξ
      flow_.prepare(drift_);
      flow_.apply(mu);
    }
    kick_.apply(mu);
  }

 private:
  Dual product_, commutator_, half_, drift_;
  MatrixConjugation<R> kick_, flow_;
};

/// SymmetricDdb's update of R, chosen by its group's traits.
template <class R>
using SymmetricUpdateFor =
    std::conditional_t<isDynamicGroup<typename R::Group>, MatrixSymmetricUpdate<R>,
                       FixedSizeSymmetricUpdate<R>>;

template <class R>
class SymmetricDdb : public LegendreMethod<R> {
 public:
  using typename LegendreMethod<R>::G;
  using typename LegendreMethod<R>::Dual;
  using typename LegendreMethod<R>::Algebra;

  SymmetricDdb(std::shared_ptr<const LiePoissonSystem<G>> system, R retraction = R(),
               LegendreForm form = LegendreForm::kLagrangian, SolverOptions options = {})
      : LegendreMethod<R>(std::move(system), std::move(retraction), form, options) {}

  std::string name() const override { return this->nameWith("sddb-"); }

  Dual step(const Dual& mu, double t, double h) override { return this->stepInPlace(mu, t, h); }

  /// The one-step symmetric DDB in place on any group: solve the half-force Legendre equation,
  /// then μ ← Ad*_{τ(hφ/2) τ(hξ) τ(hφ/2)} μ (SymmetricUpdateFor).
  void advance(Dual& mu, double t, double h) override {
    update_.resize(mu);
    this->legendre_.solveInPlace(
        update_.target(*this->system_, this->retraction_, this->legendre_, mu, h), mu, t, h);
    update_.apply(*this->system_, this->retraction_, this->legendre_, h, mu);
  }

 private:
  SymmetricUpdateFor<R> update_;
};

template <class R>
class PaperSymmetricDdb : public LegendreMethod<R> {
 public:
  using typename LegendreMethod<R>::G;
  using typename LegendreMethod<R>::Dual;
  using typename LegendreMethod<R>::Algebra;
  enum class Force { kMidpoint, kTrapezoidal };
  enum class ReadOut { kAsWritten, kHalfForce };

  PaperSymmetricDdb(std::shared_ptr<const LiePoissonSystem<G>> system, R retraction = R(),
                    Force force = Force::kMidpoint, ReadOut read_out = ReadOut::kAsWritten,
                    SolverOptions options = {})
      : LegendreMethod<R>(std::move(system), std::move(retraction), LegendreForm::kLagrangian,
                          options),
        force_(force),
        read_out_(read_out) {}

  std::string name() const override {
    return std::string("sddb-paper-") + R::kName +
           (force_ == Force::kTrapezoidal ? "-trapezoidal" : "") +
           (read_out_ == ReadOut::kHalfForce ? "-halfforce" : "");
  }
  void reset() override {
    LegendreMethod<R>::reset();
    started_ = false;
  }
  /// The solver's warm start and the two-step recurrence's last ξ, p and momentum.
  void saveWarmStart(BinaryRecordWriter& out) const override {
    LegendreMethod<R>::saveWarmStart(out);
    out.put(started_);
    out.put(h_);
    out.put(xi_);
    out.put(p_);
    out.put(momentum_);
    out.put(output_);
  }
  void loadWarmStart(BinaryRecordReader& in, const Dual& state) override {
    LegendreMethod<R>::loadWarmStart(in, state);
    in.get(started_);
    in.get(h_);
    in.get(xi_);
    in.get(p_);
    in.get(momentum_);
    in.get(output_);
  }

  Dual step(const Dual& mu, double t, double h) override {
    // A two-step recurrence in ξ: (re)start whenever the caller's state or h is not ours.
    start_iterations_ = 0;
    if (!started_ || h != h_ || mu != output_) start(mu, t, h);
    const Algebra hxi = h * xi_;
    const Dual pushed = G::AdDual(retraction_.tau(hxi), momentum_);  // (dτ^{-1}_{-hξ_k})* p_k
    const CoupledTarget target{*system_, retraction_, pushed, xi_, p_, h, force_};
    Dual p;
    const Algebra xi = legendre_.solve(target, pushed, t, h, p);
    momentum_ = target(xi, p);
    xi_ = xi;
    p_ = p;
    output_ = readOut(h);
    return output_;
  }
  /// The step's solve, and the restart's when the step (re)started the recurrence.
  long lastStepIterations() const override {
    return LegendreMethod<R>::lastStepIterations() + start_iterations_;
  }

 private:
  // Ad*_{φ_d(ξ_k, ξ)} N, with N = Ad*_{τ(hξ_k)} M_k.
  struct CoupledTarget {
    const LiePoissonSystem<G>& system;
    const R& retraction;
    const Dual& pushed;
    const Algebra& xi_k;
    const Dual& p_k;
    double h;
    Force force;
    template <class A, class D>
    D operator()(const A& xi, const D& p) const {
      using T = typename D::Scalar;
      A force_step;
      if (force == Force::kMidpoint) {
        const A mid = (xi + xi_k.template cast<T>()) * T(0.5);
        const D p_mid = liftGradient(*system.lagrangian(), mid);
        force_step = system.dissipation(mid, p_mid) * T(h);
      } else {
        const A phi_k = system.dissipation(Algebra(xi_k), Dual(p_k)).template cast<T>();
        force_step = (phi_k + system.dissipation(xi, p)) * T(0.5 * h);
      }
      return G::AdDual(retraction.tau(force_step), D(pushed.template cast<T>()));
    }
    template <class Xi, class P>
    Xi jacobian(const Algebra& xi, const Dual& p, const Xi& dxi, const P& dp) const {
      return jacobianByJets<G::kDim>(*this, xi, dxi, p, dp);
    }
  };

  void start(const Dual& mu, double t, double h) {
    legendre_.reset();
    if (read_out_ == ReadOut::kAsWritten) {
      momentum_ = mu;
      xi_ = legendre_.solve(mu, t, h, p_);
    } else {
      const HalfForceTarget<R> target{*system_, retraction_, mu, h};
      xi_ = legendre_.solve(target, mu, t, h, p_);
      momentum_ = target(xi_, p_);
    }
    started_ = true;
    h_ = h;
    start_iterations_ = LegendreMethod<R>::lastStepIterations();
  }

  Dual readOut(double h) const {
    if (read_out_ == ReadOut::kAsWritten) return momentum_;
    const Algebra back = (-0.5 * h) * system_->dissipation(xi_, p_);
    return G::AdDual(retraction_.tau(back), momentum_);
  }

  using LegendreMethod<R>::system_;
  using LegendreMethod<R>::retraction_;
  using LegendreMethod<R>::legendre_;
  long start_iterations_ = 0;  // the restart's solve in the last step, if it restarted
  Force force_;
  ReadOut read_out_;
  bool started_ = false;
  double h_ = 0.0;
  Algebra xi_ = Algebra::Zero();
  Dual p_ = Dual::Zero(), momentum_ = Dual::Zero(), output_ = Dual::Zero();
};

}  // namespace ddb
