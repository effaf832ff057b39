// MatrixBackend for the small groups' states: Eigen vectors (and matrices) whose size is fixed
// at compile time (SO(3)'s R³, SE(3)'s R⁶, a user's group). The same element-wise operations
// and reductions as the dense backend, so that one method body serves a small group's vector
// and a matrix group's matrix (Boost.Odeint's algebra serves every state type the same way:
// docs/design/matrix-backend.md, "The small groups' vectors"). Each operation is Eigen's
// expression written as the small groups' formulas always wrote it: no threads, no branches,
// inlined into registers; the bits are those of the expression (the dense backend's ±1
// shortcuts give the same bits: 1·x = x and (−1)·x = −x exactly).
//
// The matrix products, adjoints and LU solves of the dense backend are not here: a small
// group's vector is a coordinate vector, not an element of a matrix algebra.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/matrix_traits.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <type_traits>

namespace ddb {

template <class X, class>
struct MatrixBackend;  // core/matrix_backend.h

template <class X>
struct MatrixBackend<X, std::enable_if_t<hasFixedSize<X>>> {
  using Scalar = typename X::Scalar;
  using Entries = X;

  // ---- Element-wise operations (`out` may be an operand). ----
  EIGEN_ALWAYS_INLINE static void copy(const X& x, X& out) { out = x; }
  EIGEN_ALWAYS_INLINE static void setZero(X& x) { x.setZero(); }
  EIGEN_ALWAYS_INLINE static void scale(double a, const X& x, X& out) { out = a * x; }
  EIGEN_ALWAYS_INLINE static void divide(X& x, double a) { x = x / a; }
  EIGEN_ALWAYS_INLINE static void axpy(double a, const X& x, X& y) { y += a * x; }
  EIGEN_ALWAYS_INLINE static void sum(double a, const X& x, double b, const X& y, X& out) {
    out = a * x + b * y;
  }
  EIGEN_ALWAYS_INLINE static void sum(double a, const X& x, double b, const X& y, double c,
                                      const X& z, X& out) {
    out = a * x + b * y + c * z;
  }
  EIGEN_ALWAYS_INLINE static void addSum(double a, const X& x, double b, const X& y, X& out) {
    out += a * x + b * y;
  }
  /// out ← (((out + c₀·term(0)) + c₁·term(1)) + …) for j < count.
  template <class Coefficients, class Term>
  EIGEN_ALWAYS_INLINE static void addCombination(const Coefficients& c, const Term& term, int count,
                                                 X& out) {
    for (int j = 0; j < count; ++j) out += c(j) * term(j);
  }

  static FormattedValue describe(const X& x) { return {formatValue(x)}; }
  static constexpr bool sameShape(const X&, const X&) { return true; }
  static void zeroLike(X& x, const X&) { x.setZero(); }
  static constexpr Eigen::Index rows(const X&) { return X::RowsAtCompileTime; }
  static constexpr Eigen::Index globalSize(const X&) { return X::SizeAtCompileTime; }

  // ---- Reductions. ----
  static double frobeniusNorm(const X& x) { return x.norm(); }
  static double frobeniusDistance(const X& x, const X& y) { return (x - y).norm(); }
  /// Re ⟨x, y⟩ = Re Σ x̄_i y_i, the pairing of docs/reference/conventions.md §1.
  static double innerProduct(const X& x, const X& y) {
    return std::real(x.conjugate().cwiseProduct(y).sum());
  }
  static bool allFinite(const X& x) { return x.allFinite(); }
  /// As the dense backend's: subnormal parts to zero of the same sign, no other bit changed.
  static void flushSubnormals(X& x) {
    for (Eigen::Index i = 0; i < x.size(); ++i) x(i) = flushed(x(i));
  }
  static bool isZero(const X& x) { return (x.array() == Scalar(0)).all(); }

  static void save(BinaryRecordWriter& out, const X& x) { out.put(x); }
  static void load(BinaryRecordReader& in, X& x) { in.get(x); }

 private:
  static double flushed(double v) {
    return std::fpclassify(v) == FP_SUBNORMAL ? std::copysign(0.0, v) : v;
  }
  static std::complex<double> flushed(const std::complex<double>& v) {
    return {flushed(v.real()), flushed(v.imag())};
  }
};

}  // namespace ddb
