// The discrete Legendre equation of a DDB-family step (paper, Section 4.1) for small
// fixed-size groups, as a function of its unknown u: ξ in the Lagrangian form (p = ∂l/∂ξ(ξ)),
// p in the Hamiltonian form (ξ = ∂H/∂μ(p)):
//   r(u) = (dτ^{-1}_{hξ})* p − target(ξ, p),
// with its Jacobian assembled from its parts (docs/reference/conventions.md §4), no Jet in the
// path:
//   ∂r/∂u = (dτ^{-1}_{hξ})* ∂p/∂u + h ∂_x[(dτ^{-1}_x)* p]_{x = hξ} ∂ξ/∂u − ∂target/∂u,
//   ∂p/∂u = D²l(ξ), ∂ξ/∂u = I (Lagrangian form);  ∂p/∂u = I, ∂ξ/∂u = D²H(p) (Hamiltonian form).
// The Hessians come from the system's hessianTimes (analytic where the system writes them,
// Jets inside AutoDiff where it gives only l or H), ∂_x(dτ^{-1}_x)* from the retraction
// (closed forms for SO(3) and SE(3), Jets otherwise), ∂target/∂u from the target.
#pragma once

#include <ddb/core/lie_poisson_system.h>

#include <Eigen/Core>
#include <type_traits>

namespace ddb {

enum class LegendreForm { kLagrangian, kHamiltonian };

/// The target of DDB's Legendre equation: a fixed momentum (no derivative in u). Matrix
/// groups may hold it as another matrix type (a distributed matrix, core/matrix_backend.h).
template <class G, class Dual = typename G::template Dual<double>>
struct FixedMomentum {
  const Dual& momentum;
  template <class A, class D>
  D operator()(const A&, const D&) const {
    return momentum.template cast<typename D::Scalar>();
  }
  template <class Xi, class P>
  Xi jacobian(const typename G::template Algebra<double>&, const typename G::template Dual<double>&,
              const Xi&, const P&) const {
    return Xi::Zero();
  }
};

/// r(u) and ∂r/∂u; a TinyLevenbergMarquardt function (NUM_RESIDUALS = NUM_PARAMETERS = kDim).
template <class R, class Target>
struct LegendreEquation {
  using G = typename R::Group;
  static constexpr int kDim = G::kDim;
  using Scalar = double;
  enum { NUM_RESIDUALS = kDim, NUM_PARAMETERS = kDim };
  template <class T>
  using AlgebraT = typename G::template Algebra<T>;
  template <class T>
  using DualT = typename G::template Dual<T>;
  using Square = Eigen::Matrix<double, kDim, kDim>;
  /// DDB's target M_k does not depend on u: its zero Jacobian is not subtracted.
  static constexpr bool kFixedTarget = std::is_same_v<Target, FixedMomentum<G>>;

  const LiePoissonSystem<G>& system;
  const R& retraction;
  const Target& target;
  double h;
  LegendreForm form;

  /// ξ and p at the unknown u (double or Jet).
  template <class T>
  void unpack(const T* u, AlgebraT<T>& xi, DualT<T>& p) const {
    if (form == LegendreForm::kLagrangian) {
      xi = Eigen::Map<const AlgebraT<T>>(u);
      p = liftGradient(*system.lagrangian(), xi);
    } else {
      p = Eigen::Map<const DualT<T>>(u);
      xi = system.velocity(p);
    }
  }

  /// r(u), scalar-generic: on Jets it is the tests' independent check of the Jacobian.
  template <class T>
  bool residual(const T* u, T* r) const {
    AlgebraT<T> xi;
    DualT<T> p;
    unpack(u, xi, p);
    Eigen::Map<DualT<T>> out(r);
    out = retraction.dTauInverseDual(AlgebraT<T>(xi * T(h)), p) - target(xi, p);
    return true;
  }

  /// The residual at momentum p, with ξ = ∂H/∂μ(p): the fixed-point map p ← p − r
  /// of the predictor sweeps, in either form.
  DualT<double> residualAtMomentum(const DualT<double>& p) const {
    const AlgebraT<double> xi = system.velocity(p);
    return retraction.dTauInverseDual(AlgebraT<double>(h * xi), p) - target(xi, p);
  }

  /// TinyLevenbergMarquardt's interface: r(u) and, if `jacobian` is not null, ∂r/∂u (column-major).
  bool operator()(const double* u, double* r, double* jacobian) const {
    AlgebraT<double> xi;
    DualT<double> p;
    unpack(u, xi, p);
    const AlgebraT<double> hxi = h * xi;
    Eigen::Map<DualT<double>> out(r);
    out = retraction.dTauInverseDual(hxi, p) - target(xi, p);
    if (jacobian == nullptr) return true;
    // One of ∂p/∂u, ∂ξ/∂u is the identity: its product is not formed (a 6×6 product is 216
    // multiply-adds, the heavy top's Jacobian's largest part).
    Eigen::Map<Square> out_jacobian(jacobian);
    Square hessian;
    if (form == LegendreForm::kLagrangian) {
      hessian = hessianMatrix(*system.lagrangian(), xi);
      out_jacobian.noalias() = retraction.dTauInverseDualMatrix(hxi) * hessian;
      out_jacobian += h * retraction.dTauInverseDualJacobian(hxi, p);
    } else {
      hessian = hessianMatrix(system.hamiltonian(), p);
      out_jacobian = retraction.dTauInverseDualMatrix(hxi);
      out_jacobian.noalias() += (h * retraction.dTauInverseDualJacobian(hxi, p)) * hessian;
    }
    if constexpr (!kFixedTarget) {
      const Square identity = Square::Identity();
      out_jacobian -= form == LegendreForm::kLagrangian ? target.jacobian(xi, p, identity, hessian)
                                                        : target.jacobian(xi, p, hessian, identity);
    }
    return true;
  }
};

}  // namespace ddb
