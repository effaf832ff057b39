// MatrixBackend<CudaMatrix>: the matrix backend (core/matrix_backend.h,
// docs/design/matrix-backend.md) of a matrix in one GPU's memory, so that the matrix groups'
// step formulas run unchanged on the device: SUNOn<CudaMatrix> with the method table's
// kBackendMatrixGroups family, integrate() and Relaxation. Products are cuBLAS's zgemm, LU
// factors and solves cuSOLVER's zgetrf/zgetrs (cuda/cuda_lu.h), the exponential's eigenbasis
// cuSOLVER's zheevd (cuda/cuda_eigenbasis.h), everything else the kernels
// of cuda/detail/cuda_kernels.cu. Values leave the device only where a formula branches on
// them (the reductions return a double) and in save, describe and sampleEntries.
//
// The element-wise operations are compiled without fused multiply-adds and evaluate the dense
// backend's expressions, so they take its bits; the reductions add in a fixed tree of their
// own (the same bits run after run on one device, not the dense backend's), and the products
// are cuBLAS's. Every operation runs in its operands' context (cuda/cuda_context.h): its stream,
// handles and scratch; operands of two contexts are refused (InvalidArgument).
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/cuda/cuda_eigenbasis.h>
#include <ddb/cuda/cuda_lu.h>
#include <ddb/cuda/cuda_matrix.h>

#include <Eigen/Core>
#include <complex>
#include <vector>

namespace ddb {

template <>
struct MatrixBackend<CudaMatrix> {
  using X = CudaMatrix;
  using Scalar = std::complex<double>;
  using Lu = CudaLu;
  using Eigenbasis = CudaEigenbasis;
  /// CudaEigenbasis works in its own coordinates too (toBasis, fromBasis, weigh), on which the
  /// dual numbers' eigenbasis is built (core/dual_eigenbasis.h).
  static constexpr bool kEigenbasisCoordinates = true;

  // ---- Element-wise operations (the contract's table): the dense backend's expressions. ----
  static void copy(const X& x, X& out);
  static void setZero(X& x);
  static void scale(double a, const X& x, X& out);
  static void divide(X& x, double a);
  static void axpy(double a, const X& x, X& y);
  static void sum(double a, const X& x, double b, const X& y, X& out);
  static void sum(double a, const X& x, double b, const X& y, double c, const X& z, X& out);
  static void addSum(double a, const X& x, double b, const X& y, X& out);
  /// out ← ((out + c(0)·term(0)) + c(1)·term(1)) + …: one axpy per term, the same
  /// expression as the dense backend's blocked pass.
  template <class Coefficients, class Term>
  static void addCombination(const Coefficients& c, const Term& term, int count, X& out) {
    for (int j = 0; j < count; ++j) axpy(c(j), term(j), out);
  }
  /// Named by its size and Frobenius norm (its entries stay on the device).
  static FormattedValue describe(const X& x);

  static bool sameShape(const X& x, const X& like) {
    return x.rows() == like.rows() && x.cols() == like.cols();
  }
  static void zeroLike(X& x, const X& like);
  static Eigen::Index rows(const X& x) { return x.rows(); }
  static Eigen::Index globalSize(const X& x) { return x.size(); }

  // ---- Coupling functions. ----
  static void multiply(const X& a, const X& b, X& out);
  static void multiplyAdd(double s, const X& a, const X& b, X& out);
  static void addAdjoint(double s, const X& x, X& out);
  static void makeSkewHermitian(X& x);
  static Scalar trace(const X& x);
  static void addToDiagonal(X& x, Scalar c);
  static double frobeniusNorm(const X& x);
  static double frobeniusDistance(const X& x, const X& y);
  /// The dense backend's rule: |z| from the squares, hypot's where they may have under- or
  /// overflowed (MatrixBackend<Eigen::MatrixXcd>::squaresWereExact).
  static double oneNorm(const X& x);
  static double innerProduct(const X& x, const X& y);
  static bool allFinite(const X& x);
  static void flushSubnormals(X& x);
  static bool isZero(const X& x);
  /// out(s) = x at column-major linear index indices(s): gathered on the device, one copy back
  /// (through x's context's buffers: no allocation once they have grown to the sample's size).
  template <class Indices, class Out>
  static void sampleEntries(const X& x, const Indices& indices, Out& out) {
    std::vector<long>& linear = sampleIndices(x);
    std::vector<Scalar>& values = sampleValues(x);
    linear.resize(static_cast<std::size_t>(indices.size()));
    values.resize(linear.size());
    for (std::size_t s = 0; s < linear.size(); ++s) {
      linear[s] = static_cast<long>(indices(static_cast<Eigen::Index>(s)));
    }
    gather(x, linear, values);
    for (std::size_t s = 0; s < linear.size(); ++s) out(static_cast<Eigen::Index>(s)) = values[s];
  }
  /// The whole matrix through this process's memory, as the dense backend's record (the same
  /// bytes: a checkpoint moves between the CPU and the GPU).
  static void save(BinaryRecordWriter& out, const X& x);
  static void load(BinaryRecordReader& in, X& x);

 private:
  // The host buffers of sampleEntries, x's context's.
  static std::vector<long>& sampleIndices(const X& x);
  static std::vector<Scalar>& sampleValues(const X& x);
  static void gather(const X& x, const std::vector<long>& linear, std::vector<Scalar>& values);
};

}  // namespace ddb
