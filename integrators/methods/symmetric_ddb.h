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

  Dual step(const Dual& mu, double t, double h) override {
    if constexpr (isDynamicGroup<G>) {
      return this->stepInPlace(mu, t, h);
    } else {
      Dual p;
      const HalfForceTarget<R> target{*this->system_, this->retraction_, mu, h};
      const Algebra xi = this->legendre_.solve(target, mu, t, h, p);
      const Algebra half = (0.5 * h) * this->system_->dissipation(xi, p);
      const Algebra hxi = h * xi;
      const auto kick = this->retraction_.tau(half);
      return G::AdDual(G::compose(G::compose(kick, this->retraction_.tau(hxi)), kick), mu);
    }
  }

  /// Matrix groups: the same step in place, each factor of Ad*_{τ(hφ/2) τ(hξ) τ(hφ/2)} applied
  /// as an increment (matrix_conjugation.h), with preallocated workspaces. The solver accepts
  /// the p at which it evaluated the target last, so the first factor applied to μ is the
  /// target's value, the kick is still prepared at that p's φ, and the middle factor uses what
  /// the solve left: the frozen solution (Cayley, one product) or ξ's eigenbasis (exp).
  void advance(Dual& mu, double t, double h) override {
    if constexpr (isDynamicGroup<G>) {
      auto& solver = this->legendre_;
      matrix_.resize(mu);
      solver.solveInPlace(MatrixTarget{*this, mu, h}, mu, t, h);
      MatrixBackend<Dual>::copy(solver.target(), mu);
      if (!MatrixRetraction<R>::applySolvedFlow(solver, h, matrix_.flow, mu)) {
        applyFlow(solver.velocity(), h, mu);
      }
      matrix_.kick.apply(mu);
    } else {
      mu = step(mu, t, h);
    }
  }

 private:
  // The workspaces of the matrix-group step.
  struct MatrixWorkspace {
    Dual product, commutator, half, drift;
    MatrixConjugation<R> kick, flow;

    /// The matrices of mu's shape (and layout); nothing if they have it already.
    void resize(const Dual& mu) {
      using B = MatrixBackend<Dual>;
      if (B::sameShape(product, mu)) return;
      for (Dual* m : {&product, &commutator, &half, &drift}) B::zeroLike(*m, mu);
    }
  };
  struct NoWorkspace {};

  /// The half-force target Ad*_{τ(hφ(ξ, p)/2)} μ, written into the solver's workspace; the
  /// kick stays prepared at this p's φ.
  struct MatrixTarget {
    SymmetricDdb& method;
    const Dual& mu;
    double h;
    void evaluateInto(const Dual& xi, const Dual& p, Dual& out) const {
      MatrixWorkspace& w = method.matrix_;
      if constexpr (MatrixRetraction<R>::kSweep == MatrixSweep::kProductForm) {
        // The solver's a p of this p: no product.
        method.system_->halfStepDissipationInto(method.legendre_.halfStepTimesSolution(),
                                                w.commutator, w.half);
      } else {
        method.system_->dissipationInto(p, xi, 0.5 * h, w.product, w.commutator, w.half);
      }
      MatrixBackend<Dual>::copy(mu, out);
      w.kick.prepare(w.half);
      w.kick.apply(out);
    }
  };

  /// μ ← Ad*_{τ(hξ)} μ, τ(hξ) formed from ξ.
  void applyFlow(const Dual& xi, double h, Dual& mu) {
    MatrixBackend<Dual>::scale(h, xi, matrix_.drift);
    matrix_.flow.prepare(matrix_.drift);
    matrix_.flow.apply(mu);
  }

  std::conditional_t<isDynamicGroup<G>, MatrixWorkspace, NoWorkspace> matrix_;
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
