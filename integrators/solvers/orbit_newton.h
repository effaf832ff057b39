// OrbitNewton: Newton's method for a steady state on the coadjoint orbit of μ₀
// (docs/guide/steady-states.md, "Newton on the orbit"). With a positive metric the double-bracket
// flow stops exactly at the critical points of H on the orbit (dH/dt = −k(ad*_ξ μ, ad*_ξ μ),
// Proposition 3.3), so a search for them need not follow the flow's time: its fast damped
// modes bound every explicit step and its slow ones make the tail long
// (docs/results/steady-states.md, "Measured"). The orbit is parametrised around μ by the Cayley
// conjugation
//   μ(x) = Ad*_{cay x} μ,  x in the algebra,  d/dx H(μ(x))|₀ = −ad*_ξ μ,  ξ = ∂H/∂μ,
// and the search minimises f = σH, σ = +1 where the flow lowers H (α > 0), −1 where it raises
// it. Each iteration:
//  1. the Newton direction v ≈ −J⁻¹∇f, ∇f = −σ ad*_ξ μ, by preconditioned conjugate
//     gradients truncated à la Steihaug (at the trust radius Δ or at negative curvature),
//     with J v = −σ(ad*_ξ δμ + ad*_{δξ} μ), δμ = ad*_v μ, δξ = D²H(μ)[δμ], the derivative
//     of the gradient along v; stop at ‖res‖ ≤ min(½, √r)‖∇f‖ (superlinear convergence);
//  2. the step μ' = μ(s v), s = 1, ½, ¼, … until accepted: f falls by kArmijo·s|⟨∇f, v⟩|
//     up to rounding, or, where the model's decrease is below kResolvable roundings of f
//     (energy differences measure nothing there), f does not rise beyond rounding and the
//     residual r falls;
//  3. Δ doubles (up to kMaxRadius) after a full step to the radius that the model predicted
//     well, and shrinks after a poor or shortened one.
// Every accepted state is a conjugate of the last (on the orbit: the Casimirs are kept to
// rounding, as by the DDB steps) with f no higher beyond rounding: the energy moves the way
// the flow moves it, at every step. The steady state reached is a critical point near the
// path, not the flow's limit from μ₀ (docs/guide/steady-states.md compares them).
// On matrix groups every operation is the backend's (docs/design/matrix-backend.md): the
// brackets are products and adjoints, the CG's vectors combine by its element-wise
// operations and pair by its innerProduct, the preconditioner is its Eigenbasis. ∇f and J are
// those of that inner product: the pairing's differentials −σ ad*_ξ μ and J v through the
// pairing's Riesz map (rieszMapInPlace: the identity, but on SU(N) ⋉ su(N)*, whose pairing
// swaps the parts).
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/detail/energy_round_off.h>
#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/integrators/solvers/cayley_conjugation.h>
#include <ddb/integrators/solvers/orbit_preconditioner.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace ddb {

template <class G>
class OrbitNewton {
 public:
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;
  using B = MatrixBackend<Dual>;  ///< the arithmetic (a small group's too)

  static constexpr double kFirstRadius = 0.1;  ///< Δ of the first step, on ‖x‖
  static constexpr double kMaxRadius = 1.0;    ///< Δ's cap: cay x stays far from its pole
  static constexpr double kArmijo = 1e-4;
  static constexpr double kResolvable = 100.0;  ///< model decreases below this many roundings
  static constexpr int kMaxHalvings = 30;       ///< of s, before the iteration fails
  static constexpr int kCgPerDimension = 3;     ///< CG's cap, per entry of μ

  /// What one accepted iteration did.
  struct Report {
    double length = 0.0;     ///< ‖s v‖, the step on the orbit
    int halvings = 0;        ///< of s before the step was accepted
    long cg_iterations = 0;  ///< Hessian products of the direction
  };

  /// sigma = +1 lowers H (the flow's direction with α > 0), −1 raises it.
  OrbitNewton(const LiePoissonSystem<G>& system, double sigma)
      : system_(system), sigma_(sigma > 0 ? 1.0 : -1.0) {}

  /// One iteration from mu, with its energy: true if a step was accepted (mu and energy are
  /// the new state's), false if none of kMaxHalvings step lengths was (mu unchanged).
  bool advance(Dual& mu, double& energy, Report& report) {
    if (!evaluated_) {
      evaluate(mu, now_);
      evaluated_ = true;
    }
    report = Report();
    report.cg_iterations = direction(mu, 0.0, radius_);
    double slope = dot(now_.gradient, v_);
    if (!(slope < 0)) {
      // Not a descent direction (rounding near a steady state): the preconditioned gradient.
      precondition(now_.gradient, v_);
      scale(-std::min(1.0, radius_ / norm(v_)), v_, v_);
      slope = dot(now_.gradient, v_);
    }
    hessianTimes(now_, v_, jv_);
    const double model = slope + 0.5 * dot(v_, jv_);  // f's change to second order, s = 1
    const auto step = lineSearch(mu, energy, slope, model, true, report);
    if (!step) return false;
    if (step->resolvable) {
      const double ratio = step->fall / (step->s * model);
      if (step->s == 1.0 && ratio > 0.75 && report.length >= 0.99 * radius_) {
        radius_ = std::min(2.0 * radius_, kMaxRadius);
      } else if (ratio < 0.25 || step->s < 1.0) {
        radius_ = std::max(0.25 * radius_, report.length);
      }
    }
    roundoff_ = !step->resolvable;
    return true;
  }

  /// The dissipative factor of LinearlyImplicitDdb (docs/guide/steady-states.md, "A dissipative
  /// factor that lowers the energy at any h"): from mu, one Newton step of the minimizing
  /// movement min_x f(μ(x)) + ‖x‖²/(2τ), τ = h|α|, i.e. v ≈ −(J + I/τ)⁻¹∇f by preconditioned
  /// CG (linearly implicit Euler on the gradient flow ẋ = −∇f, whose explicit step −τ∇f is
  /// DDB's hφ), then mu ← μ(s v) with s = 1, ½, … the first that lowers f by Armijo's rule
  /// (or, below resolvable energy differences, does not raise it beyond rounding). f never
  /// rises, whatever τ; mu is unchanged (false) if no s was accepted. residual() is then
  /// mu's r.
  bool advanceProximal(Dual& mu, double& energy, double tau, Report& report) {
    evaluate(mu, now_);
    evaluated_ = false;  // mu moves between calls: the search's cached evaluation is stale
    report = Report();
    if (!(now_.relative > 0)) return true;  // at rest: no step
    report.cg_iterations = direction(mu, 1.0 / tau, kMaxRadius);
    // v exactly in the algebra: the matrix Cayley conjugation takes (I − b)⁻¹ = ((I + b)⁻¹)ᴴ,
    // true for a skew-Hermitian b only, and CG's v is skew-Hermitian only to rounding.
    G::projectToAlgebra(v_);
    double slope = dot(now_.gradient, v_);
    if (!(slope < 0)) {
      // CG's J is the derivative of the gradient field, symmetric only at a steady state (its
      // antisymmetric part is of the size of ∇f): its direction may not descend. The
      // preconditioned gradient, scaled by about τ, does.
      precondition(now_.gradient, v_);
      scale(-std::min(1.0, kMaxRadius / norm(v_)), v_, v_);
      slope = dot(now_.gradient, v_);
      if (!(slope < 0)) return true;  // ∇f is rounding: at rest, no step
    }
    return lineSearch(mu, energy, slope, slope, false, report).has_value();
  }

  /// ∇f and J v at mu, in the backend's inner product, as the search takes them (for checks
  /// against differences along the orbit: tests/unit/test_zeitlin_mhd.cc). The next advance
  /// evaluates its state anew.
  void gradientAndHessianProduct(const Dual& mu, const Algebra& v, Algebra& gradient, Algebra& jv) {
    evaluate(mu, now_);
    evaluated_ = false;
    B::zeroLike(gradient, mu);
    B::zeroLike(jv, mu);
    copy(now_.gradient, gradient);
    hessianTimes(now_, v, jv);
  }

  /// r at the state of the last evaluation (the last accepted state, or the unchanged one).
  double residual() const { return now_.relative; }

  /// Δ, for the record.
  double radius() const { return radius_; }

  /// The search's state besides μ (Δ, and whether the last step was past rounding).
  void save(BinaryRecordWriter& out) const {
    out.tag("orbit newton");
    out.put(radius_);
    out.put(static_cast<long>(roundoff_));
  }
  void load(BinaryRecordReader& in) {
    in.expectTag("orbit newton");
    long roundoff = 0;
    in.get(radius_);
    in.get(roundoff);
    if (!(radius_ > 0 && radius_ <= kMaxRadius) || (roundoff != 0 && roundoff != 1)) {
      throw CorruptRecord("orbit newton state");
    }
    roundoff_ = roundoff == 1;
    evaluated_ = false;
  }

 private:
  // At μ: ξ, the argument the Hamiltonian saw (matrix groups: Pμ) and ∇f = −σ R ad*_ξ μ, with
  // relative = ‖∇f‖/(‖ξ‖ ‖μ‖), the residual r of SteadyStateProbe.
  struct Evaluation {
    Dual argument;
    Algebra xi, gradient;
    double relative = 0.0;
  };

  void evaluate(const Dual& mu, Evaluation& e) {
    allocate(mu);
    if (!B::sameShape(e.argument, mu)) {
      for (Dual* m : {&e.argument, &e.xi, &e.gradient}) B::zeroLike(*m, mu);
    }
    system_.velocityInto(mu, e.argument, e.xi);
    system_.coadjointInto(e.xi, e.argument, product_, e.gradient);
    scale(-sigma_, e.gradient, e.gradient);
    rieszMapInPlace<G>(e.gradient);
    const double size = norm(e.xi) * norm(e.argument);
    e.relative = size > 0 ? norm(e.gradient) / size : 0.0;
  }

  // out = J v at e: −σR(ad*_ξ δμ + ad*_{δξ} μ), δμ = ad*_v μ, δξ = D²H(μ)[δμ].
  void hessianTimes(const Evaluation& e, const Algebra& v, Algebra& out) {
    system_.coadjointInto(v, e.argument, product_, moved_);
    system_.velocityDerivativeInto(e.argument, moved_, product_, dxi_);
    system_.coadjointInto(e.xi, moved_, product_, out);
    system_.coadjointInto(dxi_, e.argument, product_, added_);
    B::axpy(1.0, added_, out);
    scale(-sigma_, out, out);
    rieszMapInPlace<G>(out);
  }

  // v: truncated preconditioned CG on (J + shift) v = −∇f within ‖v‖ ≤ radius. Returns its
  // iterations. The search (shift 0) stops at ‖res‖ ≤ min(½, √r)‖∇f‖; the minimizing
  // movement (shift 1/τ) also at ‖res‖ ≤ (ρ/shift)‖∇f‖, ρ the first Rayleigh quotient of J:
  // v's error is then O(τ²ρ‖∇f‖), within the step's own O(h²).
  long direction(const Dual& mu, double shift, double radius) {
    const Algebra& g = now_.gradient;
    if (!preconditioner_.refresh(now_.argument, now_.xi, shift)) {
      throw NonFiniteState("orbit newton", -1, NAN, NAN, B::describe(mu), "state");
    }
    setZero(v_);
    scale(-1.0, g, res_);
    precondition(res_, z_);
    copy(z_, p_);
    double rz = dot(res_, z_);
    double stop = (shift > 0 ? 0.5 : std::min(0.5, std::sqrt(now_.relative))) * norm(g);
    const long cap = std::max<long>(100, kCgPerDimension * static_cast<long>(unknowns(mu)));
    long k = 0;
    while (k < cap && norm(res_) > stop) {
      hessianTimes(now_, p_, jv_);
      ++k;
      if (k == 1 && shift > 0) {
        stop = std::min(stop, std::abs(dot(p_, jv_)) / dot(p_, p_) / shift * norm(g));
      }
      if (shift > 0) axpy(shift, p_, jv_);
      const double curvature = dot(p_, jv_);
      if (curvature == 0.0 || (curvature < 0.0 && !roundoff_)) {
        // Negative curvature: the search goes to the radius along p (the first time, the
        // preconditioned gradient); past rounding f cannot tell a saddle from a minimum and CG
        // goes on. The minimizing movement keeps the descent direction it has (the first time,
        // the preconditioned residual, whose preconditioner includes the shift 1/τ).
        if (k == 1) {
          if (shift > 0) {
            copy(p_, v_);
          } else {
            scale(radius / norm(p_), p_, v_);
          }
        }
        break;
      }
      const double a = rz / curvature;
      sum(1.0, v_, a, p_, x_);
      if (norm(x_) >= radius) {
        const double pp = dot(p_, p_), vp = dot(v_, p_), vv = dot(v_, v_);
        const double tau = (-vp + std::sqrt(vp * vp + pp * (radius * radius - vv))) / pp;
        axpy(tau, p_, v_);
        break;
      }
      std::swap(v_, x_);
      axpy(-a, jv_, res_);
      precondition(res_, z_);
      const double rz_next = dot(res_, z_);
      sum(1.0, z_, rz_next / rz, p_, p_);
      rz = rz_next;
    }
    if (shift > 0 && norm(v_) > radius) scale(radius / norm(v_), v_, v_);
    return k;
  }

  // The accepted step of a line search along v_ from mu: its length factor s, whether f's
  // model decrease was resolvable and f's fall σ(H(μ') − H(μ)).
  struct Accepted {
    double s, fall;
    bool resolvable;
  };

  // mu ← μ(s v_) for the first s = 1, ½, … accepted: f falls by kArmijo·s|slope| up to
  // rounding or, where s·model is below kResolvable roundings of f, f does not rise beyond
  // rounding (and, with residual_must_fall, r falls). Fills report; nothing if none was.
  std::optional<Accepted> lineSearch(Dual& mu, double& energy, double slope, double model,
                                     bool residual_must_fall, Report& report) {
    double s = 1.0;
    for (int halving = 0; halving <= kMaxHalvings; ++halving, s *= 0.5) {
      scale(s, v_, x_);
      if (!retract(mu, x_, trial_mu_)) continue;
      const double trial_energy = system_.energy(trial_mu_);
      if (!std::isfinite(trial_energy)) continue;
      evaluate(trial_mu_, trial_);
      const double rounding = energyRoundOff(energy, trial_energy);
      const double fall = sigma_ * (trial_energy - energy);
      const bool resolvable = std::abs(s * model) > kResolvable * rounding;
      const bool accepted =
          resolvable ? fall <= kArmijo * s * slope + rounding
                     : fall <= rounding && (!residual_must_fall || trial_.relative < now_.relative);
      if (!accepted) continue;
      std::swap(mu, trial_mu_);
      std::swap(now_, trial_);
      energy = trial_energy;
      report.length = s * norm(v_);
      report.halvings = halving;
      return Accepted{s, fall, resolvable};
    }
    return std::nullopt;
  }

  // An approximate inverse of J + shift (OrbitPreconditionerFor).
  void precondition(const Algebra& in, Algebra& out) { preconditioner_.apply(in, out); }

  // out = Ad*_{cay x} mu; false if it is not finite.
  bool retract(const Dual& mu, const Algebra& x, Dual& out) {
    try {
      conjugation_.prepare(x);
      B::copy(mu, out);
      conjugation_.apply(out);
      return B::allFinite(out);
    } catch (const SolveFailure&) {
      return false;
    }
  }

  // Every workspace of like's shape (and layout), once per shape.
  void allocate(const Dual& like) {
    if (B::sameShape(product_, like)) return;
    for (Dual* m : {&product_, &moved_, &dxi_, &added_, &trial_mu_}) B::zeroLike(*m, like);
    for (Algebra* m : {&v_, &x_, &res_, &z_, &p_, &jv_}) B::zeroLike(*m, like);
  }

  // The CG's arithmetic: the backend's (Eigen's expressions on a small group's vectors).
  static void copy(const Algebra& x, Algebra& out) { B::copy(x, out); }
  static void setZero(Algebra& x) { B::setZero(x); }
  static void scale(double a, const Algebra& x, Algebra& out) { B::scale(a, x, out); }
  static void axpy(double a, const Algebra& x, Algebra& y) { B::axpy(a, x, y); }
  static void sum(double a, const Algebra& x, double b, const Algebra& y, Algebra& out) {
    B::sum(a, x, b, y, out);
  }
  /// Re ⟨a, b⟩, the pairing of docs/reference/conventions.md §1.
  static double dot(const Algebra& a, const Algebra& b) { return B::innerProduct(a, b); }
  static double norm(const Algebra& a) { return B::frobeniusNorm(a); }
  static long unknowns(const Dual& mu) { return static_cast<long>(B::globalSize(mu)); }

  const LiePoissonSystem<G>& system_;
  double sigma_;
  double radius_ = kFirstRadius;
  bool roundoff_ = false;  // the last step was accepted on r, its energy change below rounding
  bool evaluated_ = false;
  Evaluation now_, trial_;
  Dual trial_mu_;
  Algebra v_, x_, res_, z_, p_, jv_;
  Dual product_, moved_, dxi_, added_;
  OrbitPreconditionerFor<G> preconditioner_;
  CayleyConjugationFor<G> conjugation_;
};

}  // namespace ddb
