// OrbitPreconditioner: an approximate inverse of the Hessian of H on the coadjoint orbit of a
// matrix group (SO(N), SU(N)), for the conjugate gradients of OrbitNewton
// (docs/guide/steady-states.md, "Newton on the orbit").
// At a steady state μ and ξ = ∂H/∂μ commute. In μ's eigenbasis, μ = V diag(iθ) Vᴴ and
// π_a = Im (Vᴴ ξ V)_aa, the Hessian's part v ↦ ad*_ξ ad*_v μ multiplies entry (a, b) of
// v̂ = Vᴴ v V by (θ_a − θ_b)(π_a − π_b); the rest, the Hamiltonian's own second derivative
// along ad*_v μ, is smoother (on the fluid, an inverse Laplacian). The Hessian's spread comes
// from the first part: pairs of nearly equal θ or π give its small eigenvalues. So this
// preconditioner divides entry (a, b) by d_ab = |(θ_a − θ_b)(π_a − π_b)|, floored at kFloor
// of the largest d_ab, and leaves the diagonal (μ's commutant, which does not move μ) alone.
// For the shifted Hessian J + s·I of the minimizing movement (OrbitNewton::advanceProximal)
// it divides by d_ab + s instead, and the diagonal by s.
// Four products per application, one decomposition and the phases π per refresh, all by the
// backend's Eigenbasis (docs/design/matrix-backend.md): the weights are a function of θ and π,
// which every backend (every rank) has alike.
#pragma once

#include <ddb/core/group_traits.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/skew_hermitian_eigenbasis.h>  // the dense backend's Eigenbasis

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace ddb {

template <class Matrix>
class OrbitPreconditioner {
 public:
  /// The floor of d_ab, relative to its largest value: it bounds the amplification of
  /// rounding along (a, b) pairs that the Hessian does not move.
  static constexpr double kFloor = 1e-8;

  /// At μ with ξ = ∂H/∂μ (both skew-Hermitian, or real skew-symmetric), for J + shift·I.
  /// False if μ's eigensolver did not converge (μ not finite).
  bool refresh(const Matrix& mu, const Matrix& xi, double shift = 0.0) {
    if (!basis_.compute(mu)) return false;
    basis_.diagonalPhasesOf(xi, pi_);
    const Eigen::VectorXd& theta = basis_.phases();
    const Eigen::Index n = theta.size();
    const auto d = [&](Eigen::Index a, Eigen::Index b) {
      return std::abs((theta(a) - theta(b)) * (pi_(a) - pi_(b)));
    };
    double largest = 0.0;
    for (Eigen::Index b = 0; b < n; ++b) {
      for (Eigen::Index a = 0; a < n; ++a) largest = std::max(largest, d(a, b));
    }
    const double floor = largest > 0 ? kFloor * largest : 1.0;
    // The weights as a function of (a, b): each rank of a distributed backend evaluates its
    // own entries only (no N×N matrix on every rank).
    basis_.setWeights([&](Eigen::Index a, Eigen::Index b) {
      return a == b ? (shift > 0 ? 1.0 / shift : 1.0) : 1.0 / (std::max(d(a, b), floor) + shift);
    });
    return true;
  }

  /// out = V [d⁻¹ ∘ (Vᴴ in V)] Vᴴ. out may be in.
  void apply(const Matrix& in, Matrix& out) { basis_.applyWeights(in, out); }

 private:
  typename MatrixBackend<Matrix>::Eigenbasis basis_;
  Eigen::VectorXd pi_;
};

/// The preconditioner of states whose Eigenbasis weighs no entries, or that have none: the
/// small groups' coordinate vectors, and SU(N) ⋉ su(N)*'s dual-number matrices, whose
/// Hessian on the orbit has no closed form in μ's eigenbasis (the entry (a, b)'s weight of
/// OrbitPreconditioner becomes, over the dual numbers, a 2×2 block of both signs: the curvature
/// alone is indefinite). The identity for the search (unpreconditioned CG), 1/shift for the
/// minimizing movement (its first CG direction is then the explicit step −τ∇f). Through the
/// backend's arithmetic, as every vector OrbitNewton combines.
template <class Matrix>
class ShiftOrbitPreconditioner {
 public:
  bool refresh(const Matrix&, const Matrix&, double shift = 0.0) {
    shift_ = shift;
    return true;
  }
  /// out may be in.
  void apply(const Matrix& in, Matrix& out) const {
    MatrixBackend<Matrix>::copy(in, out);
    if (shift_ > 0) MatrixBackend<Matrix>::divide(out, shift_);
  }

 private:
  double shift_ = 0.0;
};

namespace detail {
/// Whether X's Eigenbasis weighs entries (setWeights, applyWeights), as OrbitPreconditioner needs.
template <class X, class = void>
struct EigenbasisWeighsEntries : std::false_type {};
template <class X>
struct EigenbasisWeighsEntries<
    X, std::void_t<decltype(std::declval<typename MatrixBackend<X>::Eigenbasis&>().applyWeights(
           std::declval<const X&>(), std::declval<X&>()))>> : std::true_type {};
}  // namespace detail

/// OrbitNewton's preconditioner for G's states, chosen by their backend.
template <class G>
using OrbitPreconditionerFor =
    std::conditional_t<detail::EigenbasisWeighsEntries<typename G::template Dual<double>>::value,
                       OrbitPreconditioner<typename G::template Dual<double>>,
                       ShiftOrbitPreconditioner<typename G::template Dual<double>>>;

}  // namespace ddb
