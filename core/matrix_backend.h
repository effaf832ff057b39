// MatrixBackend<X>: what the matrix groups' step formulas are written against, so that one
// formula serves a dense matrix and a matrix distributed over MPI ranks
// (docs/distributed.md, "One step formula"). Element-wise arithmetic is done on entries(x),
// an Eigen matrix that, for all operands of one formula, holds the same entries: all of them
// for a dense matrix, this rank's blocks for a distributed one (same layout). Whatever
// couples entries goes through a static function here: products, adjoints, traces, norms,
// sampled entries and LU solves. Every reduction returns the same value on every rank,
// so that every data-dependent branch is taken alike everywhere.
//
// This primary template is the dense backend (Eigen's dynamic-size matrices, real or
// complex); distributed/distributed_backend.h specialises it for DistributedMatrix.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/detail/dense_lu.h>

#include <Eigen/Core>
#include <complex>
#include <limits>
#include <utility>

namespace ddb {

template <class X>
struct MatrixBackend {
  using Scalar = typename X::Scalar;
  using Entries = X;
  /// LU factors of A in place and solves X ← A⁻¹X, workspaces reused (factor(A) returns
  /// false when A is singular).
  using Lu = DenseLu<X>;

  static X& entries(X& x) { return x; }
  static const X& entries(const X& x) { return x; }

  /// Whether x has like's shape (and, distributed, layout).
  static bool sameShape(const X& x, const X& like) {
    return x.rows() == like.rows() && x.cols() == like.cols();
  }
  /// x ← zero of like's shape.
  static void zeroLike(X& x, const X& like) { x.setZero(like.rows(), like.cols()); }
  /// The number of rows of the whole matrix.
  static Eigen::Index rows(const X& x) { return x.rows(); }
  /// The number of entries of the whole matrix.
  static Eigen::Index globalSize(const X& x) { return x.size(); }

  /// out = a b (out aliases neither).
  static void multiply(const X& a, const X& b, X& out) { out.noalias() = a * b; }
  /// out += scale·xᴴ (out is not x).
  static void addAdjoint(double scale, const X& x, X& out) { out += scale * x.adjoint(); }
  /// x ← (x − xᴴ)/2 in place, skew-Hermitian bit for bit: entry (j, i) is −conj(entry (i, j)),
  /// the diagonal imaginary (zero for real x).
  static void makeSkewHermitian(X& x) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) {
      for (Eigen::Index i = 0; i < j; ++i) {
        const Scalar v = 0.5 * (x(i, j) - Eigen::numext::conj(x(j, i)));
        x(i, j) = v;
        x(j, i) = -Eigen::numext::conj(v);
      }
      x(j, j) = 0.5 * (x(j, j) - Eigen::numext::conj(x(j, j)));
    }
  }
  static Scalar trace(const X& x) { return x.trace(); }
  /// x ← x + c·I.
  static void addToDiagonal(X& x, Scalar c) { x.diagonal().array() += c; }

  static double frobeniusNorm(const X& x) { return x.norm(); }
  /// ‖x − y‖_F.
  static double frobeniusDistance(const X& x, const X& y) { return (x - y).norm(); }
  /// ‖x‖₁, the largest column sum of |x_ij| (an upper bound of ‖x‖₂ for normal x). |z| is
  /// √(Re² + Im²), vectorised: std::abs of a complex calls hypot, which made this norm a
  /// visible share of a fluid step (docs/design.md, "Threads"). Where |z|² may have under-
  /// or overflowed (a norm that is tiny or not finite) hypot's exact |z| is used. NaN
  /// entries make it NaN.
  static double oneNorm(const X& x) {
    const double fast = fastMagnitudes(x).colwise().sum().template maxCoeff<Eigen::PropagateNaN>();
    if (squaresWereExact(fast)) return fast;
    return x.cwiseAbs().colwise().sum().template maxCoeff<Eigen::PropagateNaN>();
  }
  /// |x_ij| = √(Re² + Im²) entry by entry (an expression on an Eigen matrix: the distributed
  /// backend's local blocks too).
  template <class Entries>
  static auto fastMagnitudes(const Entries& x) {
    return x.cwiseAbs2().cwiseSqrt();
  }
  /// Whether a norm from the squares can be trusted: entries lost below √(smallest double)
  /// are below rounding relative to a norm of at least kSquaresExact, and nothing overflowed.
  static bool squaresWereExact(double norm) {
    constexpr double kSquaresExact = 1e-100;
    return norm >= kSquaresExact && norm <= std::numeric_limits<double>::max();
  }
  /// Re tr(xᴴy), the real inner product.
  static double innerProduct(const X& x, const X& y) {
    return Eigen::numext::real(x.conjugate().cwiseProduct(y).sum());
  }
  static bool isZero(const X& x) { return x.isZero(0.0); }

  /// out(s) = x(indices(s)) with column-major linear indices into the whole matrix.
  template <class Indices, class Out>
  static void sampleEntries(const X& x, const Indices& indices, Out& out) {
    for (Eigen::Index s = 0; s < indices.size(); ++s) out(s) = x(indices(s));
  }

  /// x, whole, into a record (a warm start: OneStepMethod::saveWarmStart).
  static void save(BinaryRecordWriter& out, const X& x) { out.put(x); }
  /// x ← the matrix a record holds, of x's shape (else CorruptRecord).
  static void load(BinaryRecordReader& in, X& x) {
    X read;
    in.get(read);
    if (!sameShape(read, x)) throw CorruptRecord("a matrix of another size than the state");
    x = std::move(read);
  }
};

}  // namespace ddb
