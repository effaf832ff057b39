// SkewHermitianGroup: the closed forms shared by SO(N) (real skew-symmetric algebra)
// and SU(N) (complex skew-Hermitian algebra), N chosen at run time
// (docs/reference/conventions.md §1, "Matrix algebras"):
//   ξ, μ are N×N matrices, hat = dualHat = identity, pairing <μ, ξ> = Re tr(μᴴ ξ),
//   ad*_ξ μ = [μ, ξ],  Ad*_g μ = g⁻¹ μ g = gᴴ μ g,  (dcay⁻¹_x)* μ = (I + x/2) μ (I − x/2).
// Every formula is O(N³) at most and no operator on the N²-dimensional algebra is formed.
//
// vee and dualVee are the orthogonal projection onto skew-Hermitian matrices, u(N) (for
// real matrices: so(N)). They do not remove the trace: the Cayley map sends su(N) into
// U(N), not SU(N), and its tangent maps and the DDB Legendre unknown p live in u(N)
// (docs/reference/conventions.md §2, "Zeitlin's fluid"); projecting them would change the scheme.
#pragma once

#include <ddb/core/detail/normal_matrix_functions.h>
#include <ddb/core/errors.h>
#include <ddb/core/lie_group.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/skew_hermitian_eigenbasis.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

namespace ddb {

template <class Derived, template <class> class ScalarOf>
struct SkewHermitianGroup : LieGroupBase<Derived> {
  static constexpr int kDim = Eigen::Dynamic;
  static constexpr int kNumCasimirs = Eigen::Dynamic;

  template <class T>
  using Matrix = Eigen::Matrix<ScalarOf<T>, Eigen::Dynamic, Eigen::Dynamic>;
  template <class T>
  using Algebra = Matrix<T>;
  template <class T>
  using Dual = Matrix<T>;
  /// The spectrum of μ: the eigenvalues of the Hermitian matrix −iμ, ascending.
  template <class T>
  using Casimirs = Eigen::Matrix<T, Eigen::Dynamic, 1>;

  // ---- Minimum API ----
  template <class X>
  static X hat(const X& x) {
    return x;
  }
  template <class X>
  static X dualHat(const X& mu) {
    return mu;
  }
  /// The skew-Hermitian part (X − Xᴴ)/2: the orthogonal projection onto u(N) (so(N)).
  template <class X>
  static X vee(const X& m) {
    return X((m - m.adjoint()) * typename X::Scalar(0.5));
  }
  template <class X>
  static X dualVee(const X& m) {
    return vee(m);
  }

  /// exp(x) = I + V diag(e^{iθ} − 1) Vᴴ from the eigenpairs of the Hermitian −ix: unitary
  /// (orthogonal) to round-off, unlike a Padé approximant (skew_hermitian_eigenbasis.h).
  template <class X>
  static X exp(const X& x) {
    X g(x.rows(), x.cols());
    eigenbasisOf(x).exponential(1.0, g);
    return g;
  }

  /// log(g) = V diag(i arg λ) Vᴴ for unitary g (a normal matrix: its complex Schur form
  /// is diagonal), the branch with eigenvalues of −i log g in (−π, π].
  template <class X>
  static X log(const X& g) {
    return vee(fromComplex<X>(detail::unitaryLogarithm(toComplex(g))));
  }

  template <class X>
  static Casimirs<double> casimirs(const X& mu) {
    return detail::hermitianEigenvalues(toComplex(mu) * std::complex<double>(0, -1));
  }

  /// ‖μ‖₂ of a skew-Hermitian μ: the largest |eigenvalue| of −iμ (its spectrum, a Casimir).
  template <class X>
  static double spectralNorm(const X& mu) {
    const Casimirs<double> spectrum = Derived::casimirs(mu);
    return std::max(std::abs(spectrum(0)), std::abs(spectrum(spectrum.size() - 1)));
  }

  /// The orthogonal projection onto the algebra, in place: the skew-Hermitian part with the
  /// trace removed (su(N)), the skew-symmetric part for real matrices (so(N)). It is what a
  /// system hands its Hamiltonian, where the DDB Legendre unknown carries a trace, and what it
  /// makes of the ξ the Hamiltonian returns (docs/reference/conventions.md §2, "Systems on matrix
  /// groups"). The result is skew-Hermitian bit for bit (entry (j, i) is −conj of entry
  /// (i, j), the diagonal imaginary), and sums and real multiples of such matrices stay so:
  /// an explicit step keeps its state on the algebra up to a trace of rounding size.
  template <class X>
  static void projectToAlgebra(X& x) {
    using B = MatrixBackend<X>;
    B::makeSkewHermitian(x);  // the real diagonal is now zero
    if constexpr (Eigen::NumTraits<typename B::Scalar>::IsComplex) {
      const double mean = B::trace(x).imag() / double(B::rows(x));
      B::addToDiagonal(x, typename B::Scalar(0.0, -mean));
    }
  }

  // ---- Closed forms shadowing the deduced API ----
  template <class X>
  static X inverse(const X& g) {
    return g.adjoint();  // unitary / orthogonal
  }
  template <class X>
  static X bracket(const X& x, const X& y) {
    return x * y - y * x;
  }
  /// ad*_ξ μ = [μ, ξ].
  template <class X>
  static X adDual(const X& xi, const X& mu) {
    return mu * xi - xi * mu;
  }
  template <class X>
  static X Ad(const X& g, const X& x) {
    return g * x * g.adjoint();
  }
  /// Ad*_g μ = gᴴ μ g.
  template <class X>
  static X AdDual(const X& g, const X& mu) {
    return g.adjoint() * mu * g;
  }
  // The exponential's tangent maps in closed form (docs/reference/conventions.md §1, "Matrix
  // algebras"): ad_x multiplies entry (a, b) of x's eigenbasis by iδ, δ = θ_a − θ_b, and is
  // skew-adjoint under the trace pairing, so with f(iη) = (e^{iη} − 1)/(iη)
  //   dexp_x = f(ad_x),  dexp⁻¹_x = 1/f(ad_x),  (dexp⁻¹_x)* = 1/f(−ad_x).
  // They shadow LieGroupBase's series (which stay the tests' independent reference).

  /// dexp_x y = Σ_j ad_x^j y / (j+1)!.
  template <class X>
  static X dexp(const X& x, const X& y) {
    X out(y.rows(), y.cols());
    eigenbasisOf(x).apply(expm1OfIOverI, 1.0, y, out);
    return out;
  }
  /// dexp⁻¹_x y = Σ_j B_j/j! ad_x^j y; poles where ad_x has an eigenvalue 2πik, k ≠ 0.
  template <class X>
  static X dexpInv(const X& x, const X& y) {
    X out(y.rows(), y.cols());
    eigenbasisOf(x).apply([](double eta) { return 1.0 / expm1OfIOverI(eta); }, 1.0, y, out);
    return out;
  }
  /// (dexp⁻¹_x)* μ = Σ_j B_j/j! (ad*_x)^j μ.
  template <class X>
  static X dexpInvDual(const X& x, const X& mu) {
    X out(mu.rows(), mu.cols());
    eigenbasisOf(x).apply([](double eta) { return 1.0 / expm1OfIOverI(-eta); }, 1.0, mu, out);
    return out;
  }
  /// The spectral radius of ad_x, max_ab |θ_a − θ_b|: exp is one-to-one on ad-radii below
  /// π, and dexp⁻¹_x has its poles at 2π (integrators/solvers/injectivity_guard.h).
  template <class X>
  static double adRadius(const X& x) {
    return eigenbasisOf(x).adRadius();
  }

  /// dcay⁻¹_x y = (I − x/2) y (I + x/2), in u(N).
  template <class X>
  static X dcayInv(const X& x, const X& y) {
    const X half = x * typename X::Scalar(0.5);
    const X I = X::Identity(x.rows(), x.cols());
    return (I - half) * y * (I + half);
  }
  /// (dcay⁻¹_x)* μ = (I + x/2) μ (I − x/2), in u(N) (not projected).
  template <class X>
  static X dcayInvDual(const X& x, const X& mu) {
    const X half = x * typename X::Scalar(0.5);
    const X I = X::Identity(x.rows(), x.cols());
    return (I + half) * mu * (I - half);
  }
  /// dcay_x y = (I − x/2)⁻¹ y (I + x/2)⁻¹, in u(N).
  template <class X>
  static X dcay(const X& x, const X& y) {
    const X half = x * typename X::Scalar(0.5);
    const X I = X::Identity(x.rows(), x.cols());
    const X left = (I - half).partialPivLu().solve(y);
    // left (I + x/2)⁻¹ = ((I + x/2)⁻ᴴ leftᴴ)ᴴ, and (I + x/2)ᴴ = I − x/2.
    return X((I - half).partialPivLu().solve(left.adjoint()).adjoint());
  }
  /// cay⁻¹(g) = 2 (g − I)(g + I)⁻¹.
  template <class X>
  static X cayInverse(const X& g) {
    const X I = X::Identity(g.rows(), g.cols());
    const X right = (g + I).adjoint().partialPivLu().solve((g - I).adjoint()).adjoint();
    return vee(X(right * typename X::Scalar(2)));
  }

  // ---- In-place kernels of the matrix-free DDB Cayley step (no allocation) ----
  // They use skew-Hermitian structure: for skew-Hermitian a and p, pa = (ap)ᴴ, so
  // [a, p] = ap − (ap)ᴴ costs one product (docs/reference/conventions.md §4).

  /// out = W − [a, p] + a p a, the fixed-point map of W = (I + a) p (I − a)
  /// (docs/reference/conventions.md §2); ap, apa are workspaces. Two products.
  template <class X>
  static void cayleyFixedPoint(const X& W, const X& a, const X& p, X& ap, X& apa, X& out) {
    MatrixBackend<X>::multiply(a, p, ap);
    cayleyFixedPointGiven(W, a, ap, apa, out);
  }
  /// The same map given the product ap = a p already formed. One product.
  template <class X>
  static void cayleyFixedPointGiven(const X& W, const X& a, const X& ap, X& apa, X& out) {
    using B = MatrixBackend<X>;
    B::multiply(ap, a, apa);
    B::sum(1.0, W, -1.0, ap, 1.0, apa, out);
    B::addAdjoint(1.0, ap, out);
  }

  /// How far M − 2[a, q] may miss Ad*_{cay(2a)} M = M − 2[a, p̃] (p̃ the solution of the frozen-a
  /// equation (I + a) p̃ (I − a) = M, whose fixed-point map carried p to next, update = ‖next −
  /// p‖): next_error for q = next, refined_error for q the frozen sweep after it (with a p a kept
  /// from p); both infinite where the frozen map need not contract. With ‖a‖₂ ≤ ‖a‖₁ and the
  /// map's rate λ ≤ 2‖a‖₂ + ‖a‖₂²: ‖p̃ − next‖ ≤ λ/(1 − λ)·update, ‖p̃ − q‖ ≤ (2‖a‖₂λ +
  /// ‖a‖₂²)/(1 − λ)·update for the refined q, and the miss is 2‖[a, p̃ − q]‖ ≤ 4‖a‖₂‖p̃ − q‖
  /// (MatrixLegendreSolver::certifyFrozenSolution compares them with rounding).
  template <class X>
  static void cayleyFrozenErrors(const X& a, const X&, const X&, double update, double& next_error,
                                 double& refined_error) {
    const double norm_a = MatrixBackend<X>::oneNorm(a);
    const double lambda = 2.0 * norm_a + norm_a * norm_a;
    if (!(lambda < 1.0)) {
      next_error = refined_error = INFINITY;
      return;
    }
    next_error = 4.0 * norm_a * lambda / (1.0 - lambda) * update;
    refined_error =
        4.0 * norm_a * (2.0 * norm_a * lambda + norm_a * norm_a) / (1.0 - lambda) * update;
  }

  /// out = [p, a] = pa − ap = (ap)ᴴ − ap given the product ap. No product.
  template <class X>
  static void commutatorFromProduct(const X& ap, X& out) {
    using B = MatrixBackend<X>;
    B::scale(-1.0, ap, out);
    B::addAdjoint(1.0, ap, out);
  }

  /// out = D_p[(I + a) p (I − a)][δ] with a = a(p) and δa = Da[δ] given:
  ///   δ + [a, δ] − a δ a + [δa, p] − (δa p a + a p δa),
  /// where a p δa = −(δa p a)ᴴ. Four products; t1, t2 workspaces.
  template <class X>
  static void cayleyLinearised(const X& a, const X& p, const X& delta, const X& delta_a, X& t1,
                               X& t2, X& out) {
    using B = MatrixBackend<X>;
    B::multiply(a, delta, t1);
    B::multiply(t1, a, t2);
    B::sum(1.0, delta, 1.0, t1, -1.0, t2, out);
    B::addAdjoint(-1.0, t1, out);
    B::multiply(delta_a, p, t1);
    B::multiply(t1, a, t2);
    B::addSum(1.0, t1, -1.0, t2, out);
    B::addAdjoint(-1.0, t1, out);
    B::addAdjoint(1.0, t2, out);
  }

  /// Checks that mu is a valid state: square, N >= 2, N <= kMaxN, finite, skew-Hermitian
  /// (skew-symmetric) to 1e-12 relative, and traceless to 1e-12 relative. The message
  /// names the parameter, its size and the largest offending entry.
  template <class X>
  static void requireState(const std::string& name, const Eigen::MatrixBase<X>& state) {
    const typename X::PlainObject mu = state;
    if (mu.rows() != mu.cols() || mu.rows() < 2 || mu.rows() > kMaxN) {
      throwInvalid(name, std::to_string(mu.rows()) + "x" + std::to_string(mu.cols()) + " matrix",
                   "must be square N x N with 2 <= N <= " + std::to_string(kMaxN));
    }
    requireFinite(name, mu);
    const double scale = mu.norm();
    const typename X::PlainObject sym = mu + mu.adjoint();
    if (sym.norm() > 1e-12 * scale) {
      throwInvalid(name, formatValue(sym),
                   std::string("must be ") + Derived::kAlgebraName +
                       ": mu + mu^H must vanish to 1e-12 relative");
    }
    const double trace = std::abs(mu.trace());
    if (trace > 1e-12 * scale) {
      throwInvalid(name + " trace", formatValue(trace), "must be 0 to 1e-12 relative");
    }
  }

  /// The largest N accepted for a state: one 4096×4096 complex matrix is 256 MiB and a
  /// DDB Cayley step keeps about 25 of them (solver workspaces, the predictor's 8
  /// corrections, the transport's), 31 more once Newton–Krylov is needed (GMRES's basis).
  static constexpr Eigen::Index kMaxN = 4096;

 private:
  using Complex = Eigen::MatrixXcd;
  template <class X>
  static Complex toComplex(const X& x) {
    return x.template cast<std::complex<double>>();
  }
  template <class X>
  static SkewHermitianEigenbasis<X> eigenbasisOf(const X& x) {
    SkewHermitianEigenbasis<X> basis;
    if (!basis.compute(x)) throwInvalid("x", "a matrix with non-finite entries", "must be finite");
    return basis;
  }
  template <class X, class E>
  static X fromComplex(const E& e) {
    if constexpr (Eigen::NumTraits<typename X::Scalar>::IsComplex) {
      return X(e);
    } else {
      return X(Complex(e).real());
    }
  }
};

}  // namespace ddb
