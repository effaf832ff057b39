// DualMatrix<X>: a matrix over the dual numbers R[ε], ε² = 0, stored as two matrices of a backend
// X, x = x₀ + ε x₁, and MatrixBackend<DualMatrix<X>>, its arithmetic through X's backend
// (docs/design/matrix-backend.md). su(N) ⊗ R[ε] is the Lie algebra of SU(N) ⋉ su(N)*
// (groups/dual_number_sun.h; docs/reference/conventions.md §1, "SU(N) over the dual numbers"),
// so the matrix groups' formulas, written against MatrixBackend, run on it unchanged:
//   products  (a₀ + εa₁)(b₀ + εb₁) = a₀b₀ + ε(a₁b₀ + a₀b₁)   (three of X's products),
//   adjoints  entry by entry, part by part (ε is real), and every element-wise operation part
//             by part,
//   LU solves (A₀ + εA₁)⁻¹ b = x₀ + ε A₀⁻¹(b₁ − A₁x₀), x₀ = A₀⁻¹b₀ (one factorisation, of A₀).
// The solvers' own inner product, norms and sample are Euclidean over both parts (they measure
// iterates, not energies): innerProduct adds the parts' inner products, frobeniusNorm is the
// norm of both parts together, and oneNorm, which the Cayley solver uses to bound the norm of
// multiplying by x, is ‖x₀‖₁ + ‖x₁‖₁ (multiplying by x maps (p₀, p₁) to (x₀p₀, x₁p₀ + x₀p₁),
// of norm at most ‖x₀‖₂ + ‖x₁‖₂).
// A product whose factor is exactly zero is not formed: a part that is zero stays zero, and a
// state with one part zero costs X's one product per product, with X's bits (the magnetic fluid
// with Θ = 0 is the fluid, systems/zeitlin_mhd.h).
// On the dense, distributed and CUDA complex parts the backend's Eigenbasis is DualEigenbasis
// (core/dual_eigenbasis.h, which its users include): the exponential methods run on it. Parts
// whose eigenbasis has no coordinates have no Eigenbasis. On every part the Newton search and the
// linearly implicit Cayley step run with the shift's preconditioner, the backend's arithmetic alone
// (no entries' weights over the dual numbers: integrators/solvers/orbit_preconditioner.h).
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/matrix_backend.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <type_traits>

namespace ddb {

/// x = real + ε·eps over the dual numbers (ε² = 0), both parts matrices of one shape.
template <class X>
struct DualMatrix {
  using Scalar = typename MatrixBackend<X>::Scalar;
  X real;  ///< x₀, the coefficient of 1
  X eps;   ///< x₁, the coefficient of ε

  /// Exchanges both parts with other's (no copy: the solvers swap their iterates).
  void swap(DualMatrix& other) {
    real.swap(other.real);
    eps.swap(other.eps);
  }
};

template <class X>
class DualEigenbasis;  // core/dual_eigenbasis.h

namespace detail {
/// Whether X's complex Eigenbasis works in its own coordinates (kEigenbasisCoordinates), as
/// DualEigenbasis needs.
template <class X, class = void>
struct HasEigenbasisCoordinates : std::false_type {};
template <class X>
struct HasEigenbasisCoordinates<
    X, std::enable_if_t<MatrixBackend<X>::kEigenbasisCoordinates &&
                        std::is_same_v<typename MatrixBackend<X>::Scalar, std::complex<double>>>>
    : std::true_type {};

/// MatrixBackend<DualMatrix<X>>'s Eigenbasis, where X's has coordinates.
template <class X, class = void>
struct DualEigenbasisMember {};
template <class X>
struct DualEigenbasisMember<X, std::enable_if_t<HasEigenbasisCoordinates<X>::value>> {
  using Eigenbasis = DualEigenbasis<X>;
};
}  // namespace detail

/// The shift's preconditioner (ShiftOrbitPreconditioner) needs only the arithmetic, which every
/// part's backend has: on dual-number matrices of any part the search runs.
template <class X>
struct HasOrbitPreconditioner<DualMatrix<X>> : std::true_type {};

template <class X>
struct MatrixBackend<DualMatrix<X>, void> : detail::DualEigenbasisMember<X> {
  using D = DualMatrix<X>;
  using Part = MatrixBackend<X>;
  using Scalar = typename Part::Scalar;

  /// LU of A = A₀ + εA₁: A₀ factored in place by X's LU, A₁ kept as it is.
  class Lu {
   public:
    bool factor(D& a) { return lu_.factor(a.real); }
    /// b ← A⁻¹b: x₀ = A₀⁻¹b₀, then x₁ = A₀⁻¹(b₁ − A₁x₀).
    void solve(const D& a, D& b) {
      const bool real_zero = Part::isZero(b.real);
      if (!real_zero) {
        lu_.solve(a.real, b.real);
        if (!Part::isZero(a.eps)) Part::multiplyAdd(-1.0, a.eps, b.real, b.eps);
      }
      if (!Part::isZero(b.eps)) lu_.solve(a.real, b.eps);
    }

   private:
    typename Part::Lu lu_;
  };

  // ---- Element-wise operations, part by part ----
  static void copy(const D& x, D& out) {
    Part::copy(x.real, out.real);
    Part::copy(x.eps, out.eps);
  }
  static void setZero(D& x) {
    Part::setZero(x.real);
    Part::setZero(x.eps);
  }
  static void scale(double a, const D& x, D& out) {
    Part::scale(a, x.real, out.real);
    Part::scale(a, x.eps, out.eps);
  }
  static void divide(D& x, double a) {
    Part::divide(x.real, a);
    Part::divide(x.eps, a);
  }
  static void axpy(double a, const D& x, D& y) {
    Part::axpy(a, x.real, y.real);
    Part::axpy(a, x.eps, y.eps);
  }
  static void sum(double a, const D& x, double b, const D& y, D& out) {
    Part::sum(a, x.real, b, y.real, out.real);
    Part::sum(a, x.eps, b, y.eps, out.eps);
  }
  static void sum(double a, const D& x, double b, const D& y, double c, const D& z, D& out) {
    Part::sum(a, x.real, b, y.real, c, z.real, out.real);
    Part::sum(a, x.eps, b, y.eps, c, z.eps, out.eps);
  }
  static void addSum(double a, const D& x, double b, const D& y, D& out) {
    Part::addSum(a, x.real, b, y.real, out.real);
    Part::addSum(a, x.eps, b, y.eps, out.eps);
  }
  template <class Coefficients, class Term>
  static void addCombination(const Coefficients& c, const Term& term, int count, D& out) {
    Part::addCombination(
        c, [&](int j) -> const X& { return term(j).real; }, count, out.real);
    Part::addCombination(
        c, [&](int j) -> const X& { return term(j).eps; }, count, out.eps);
  }

  static FormattedValue describe(const D& x) {
    return {"1-part " + Part::describe(x.real).text + ", eps-part " + Part::describe(x.eps).text};
  }

  // ---- Shape ----
  static bool sameShape(const D& x, const D& like) {
    return Part::sameShape(x.real, like.real) && Part::sameShape(x.eps, like.eps);
  }
  static void zeroLike(D& x, const D& like) {
    Part::zeroLike(x.real, like.real);
    Part::zeroLike(x.eps, like.eps);
  }
  static Eigen::Index rows(const D& x) { return Part::rows(x.real); }
  /// The entries of one part: the predictor's sample (sampleEntries) reads both parts at once.
  static Eigen::Index globalSize(const D& x) { return Part::globalSize(x.real); }

  // ---- Products and adjoints ----
  /// out = a b: a₀b₀ + ε(a₁b₀ + a₀b₁), each product only where neither factor is zero.
  static void multiply(const D& a, const D& b, D& out) {
    productInto(a.real, b.real, out.real, b.real);
    const bool first = !Part::isZero(a.eps) && !Part::isZero(b.real);
    const bool second = !Part::isZero(a.real) && !Part::isZero(b.eps);
    if (first) {
      Part::multiply(a.eps, b.real, out.eps);
      if (second) Part::multiplyAdd(1.0, a.real, b.eps, out.eps);
    } else if (second) {
      Part::multiply(a.real, b.eps, out.eps);
    } else {
      zeroPart(out.eps, b.eps);
    }
  }
  /// out += s·x y, the same three products accumulated.
  static void multiplyAdd(double s, const D& x, const D& y, D& out) {
    if (!Part::isZero(x.real) && !Part::isZero(y.real))
      Part::multiplyAdd(s, x.real, y.real, out.real);
    if (!Part::isZero(x.eps) && !Part::isZero(y.real)) Part::multiplyAdd(s, x.eps, y.real, out.eps);
    if (!Part::isZero(x.real) && !Part::isZero(y.eps)) Part::multiplyAdd(s, x.real, y.eps, out.eps);
  }
  /// out += s·xᴴ, entry by entry in each part (ε is real, so (x₀ + εx₁)ᴴ = x₀ᴴ + εx₁ᴴ).
  static void addAdjoint(double s, const D& x, D& out) {
    Part::addAdjoint(s, x.real, out.real);
    Part::addAdjoint(s, x.eps, out.eps);
  }
  static void makeSkewHermitian(D& x) {
    Part::makeSkewHermitian(x.real);
    Part::makeSkewHermitian(x.eps);
  }
  /// x ← x + c·I (c real or complex, no ε-part: the identity's multiples of the Cayley map).
  static void addToDiagonal(D& x, Scalar c) { Part::addToDiagonal(x.real, c); }

  // ---- Reductions, Euclidean over both parts ----
  static double frobeniusNorm(const D& x) {
    return std::hypot(Part::frobeniusNorm(x.real), Part::frobeniusNorm(x.eps));
  }
  static double frobeniusDistance(const D& x, const D& y) {
    return std::hypot(Part::frobeniusDistance(x.real, y.real),
                      Part::frobeniusDistance(x.eps, y.eps));
  }
  /// ‖x₀‖₁ + ‖x₁‖₁, a bound of the norm of multiplying by x (see the top of this file).
  static double oneNorm(const D& x) { return Part::oneNorm(x.real) + Part::oneNorm(x.eps); }
  static double innerProduct(const D& x, const D& y) {
    return Part::innerProduct(x.real, y.real) + Part::innerProduct(x.eps, y.eps);
  }
  static bool allFinite(const D& x) { return Part::allFinite(x.real) && Part::allFinite(x.eps); }
  static void flushSubnormals(D& x) {
    Part::flushSubnormals(x.real);
    Part::flushSubnormals(x.eps);
  }
  static bool isZero(const D& x) { return Part::isZero(x.real) && Part::isZero(x.eps); }

  /// out(s) = x₀(i) + x₁(i), i = indices(s): a linear sketch of both parts at once (the
  /// predictor fits its coefficients on it, correction_predictor.h), which is x₁'s entries
  /// exactly where x₀ is zero. x₁'s entries are sampled by chunks into a buffer on the stack: one
  /// call of the part's sampleEntries (on MPI ranks, one reduction) per kChunk entries.
  template <class Indices, class Out>
  static void sampleEntries(const D& x, const Indices& indices, Out& out) {
    constexpr Eigen::Index kChunk = 64;
    Part::sampleEntries(x.real, indices, out);
    Eigen::Matrix<Scalar, kChunk, 1> buffer;
    for (Eigen::Index first = 0; first < indices.size(); first += kChunk) {
      const Eigen::Index count = std::min(kChunk, indices.size() - first);
      auto values = buffer.head(count);
      Part::sampleEntries(x.eps, indices.segment(first, count), values);
      for (Eigen::Index k = 0; k < count; ++k) out(first + k) = out(first + k) + values(k);
    }
  }

  static void save(BinaryRecordWriter& out, const D& x) {
    Part::save(out, x.real);
    Part::save(out, x.eps);
  }
  static void load(BinaryRecordReader& in, D& x) {
    Part::load(in, x.real);
    Part::load(in, x.eps);
  }

 private:
  // out = a b, or zero of `like`'s shape where a or b is zero.
  static void productInto(const X& a, const X& b, X& out, const X& like) {
    if (Part::isZero(a) || Part::isZero(b)) {
      zeroPart(out, like);
    } else {
      Part::multiply(a, b, out);
    }
  }
  static void zeroPart(X& out, const X& like) {
    if (Part::sameShape(out, like)) {
      Part::setZero(out);
    } else {
      Part::zeroLike(out, like);
    }
  }
};

}  // namespace ddb
