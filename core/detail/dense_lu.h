// DenseLu: the LU factorisation of a square dynamic-size matrix (real or complex) and
// solves with it in place, with pivots allocated when a size first appears, then reused
// (no allocation per call). The Cayley conjugation
// (integrators/matrix_kernels/matrix_conjugation.h) factors I + b once per step and solves with it
// twice: with Debian's OpenBLAS that costs less than forming the inverse and multiplying by it
// (docs/design/architecture.md, "The Cayley conjugation by solves"). With DDB_USE_LAPACK (set by
// the build when a LAPACK and LAPACKE are found next to the BLAS) it calls ?getrf + ?getrs, which
// cost half of Eigen's own LU, the fallback (docs/design/architecture.md, "Measured, and what it
// decided").
#pragma once

#include <ddb/core/detail/blas_threads.h>
#include <ddb/core/detail/lapack.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <complex>
#include <type_traits>
#include <vector>

namespace ddb {

template <class Matrix>
class DenseLu {
 public:
  using Scalar = typename Matrix::Scalar;
  static_assert(std::is_same_v<Scalar, double> || std::is_same_v<Scalar, std::complex<double>>,
                "DenseLu factors double or std::complex<double> matrices");

  /// Factors A: with LAPACK A ← its LU factors, with Eigen's LU A is left as it is and
  /// the factors are kept here. Returns false when A is exactly singular. solve() takes the
  /// same A, so that nothing here points at the caller's matrix.
  bool factor(Matrix& A) {
    allocate(A.rows());
#ifdef DDB_USE_LAPACK
    return lapack::getrf(static_cast<lapack::Int>(A.rows()), A.data(), pivots_.data()) == 0;
#else
    lu_.compute(A);
    // Eigen's partial-pivoting LU has no singularity flag: an exactly zero pivot shows.
    return !(lu_.matrixLU().diagonal().array() == Scalar(0)).any();
#endif
  }

  /// X ← A⁻¹X, given the A of the last successful factor() (X: A's rows, any columns).
  void solve(const Matrix& A, Matrix& X) {
#ifdef DDB_USE_LAPACK
    // The columns of X are independent: under a single-threaded BLAS, one getrs per chunk of
    // columns, on the library's threads, as products are (MatrixBackend::multiply).
    if (X.cols() == 0) return;
    const auto n = static_cast<lapack::Int>(A.rows());
    const auto solveColumns = [&](long first, long count) {
      lapack::getrs(n, static_cast<lapack::Int>(count), A.data(), pivots_.data(),
                    X.col(first).data());
    };
    detail::forBlasColumnChunks(X.cols(), solveColumns);
#else
    static_cast<void>(A);
    solved_.noalias() = lu_.solve(X);  // Eigen's solve may not alias its right-hand side
    X.swap(solved_);
#endif
  }

 private:
  void allocate(Eigen::Index n) {
    if (size_ == n) return;
    size_ = n;
#ifdef DDB_USE_LAPACK
    pivots_.assign(static_cast<std::size_t>(n), 0);
#else
    lu_ = Eigen::PartialPivLU<Matrix>(n);
#endif
  }

  Eigen::Index size_ = -1;
#ifdef DDB_USE_LAPACK
  std::vector<lapack::Int> pivots_;
#else
  Eigen::PartialPivLU<Matrix> lu_;
  Matrix solved_;
#endif
};

}  // namespace ddb
