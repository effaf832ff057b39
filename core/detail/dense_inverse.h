// DenseInverse: A ← A⁻¹ in place for a square dynamic-size matrix (real or complex), with
// its pivots and workspace allocated when a size first appears, then reused (no
// allocation per call). The Cayley transport of the matrix groups inverts I − x once or
// twice per step (docs/conventions.md §4). With DDB_USE_LAPACK (set by the build when a
// LAPACK and LAPACKE are found next to the BLAS) it calls ?getrf + ?getri, which with Debian's
// OpenBLAS costs half of Eigen's own LU and solve against the identity, the fallback
// (docs/design.md, "Measured, and what it decided").
#pragma once

#include <ddb/core/detail/lapack.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <complex>
#include <type_traits>
#include <vector>

namespace ddb {

template <class Matrix>
class DenseInverse {
 public:
  using Scalar = typename Matrix::Scalar;
  static_assert(std::is_same_v<Scalar, double> || std::is_same_v<Scalar, std::complex<double>>,
                "DenseInverse inverts double or std::complex<double> matrices");

  /// A ← A⁻¹. Returns false, leaving A unspecified, when A is exactly singular.
  bool invert(Matrix& A) {
    allocate(A.rows());
#ifdef DDB_USE_LAPACK
    // The _work variants with column-major storage call ?getrf/?getri directly: no copy,
    // no NaN scan, no workspace allocation.
    const auto n = static_cast<lapack_int>(A.rows());
    const auto lwork = static_cast<lapack_int>(work_.size());
    lapack_int info = 0;
    if constexpr (std::is_same_v<Scalar, double>) {
      info = LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, n, n, A.data(), n, pivots_.data());
      if (info != 0) return false;
      info = LAPACKE_dgetri_work(LAPACK_COL_MAJOR, n, A.data(), n, pivots_.data(), work_.data(),
                                 lwork);
    } else {
      info = LAPACKE_zgetrf_work(LAPACK_COL_MAJOR, n, n, lapackData(A.data()), n, pivots_.data());
      if (info != 0) return false;
      info = LAPACKE_zgetri_work(LAPACK_COL_MAJOR, n, lapackData(A.data()), n, pivots_.data(),
                                 lapackData(work_.data()), lwork);
    }
    return info == 0;
#else
    lu_.compute(A);
    // Eigen's partial-pivoting LU has no singularity flag: an exactly zero pivot shows.
    if ((lu_.matrixLU().diagonal().array() == Scalar(0)).any()) return false;
    A.noalias() = lu_.solve(identity_);
    return true;
#endif
  }

 private:
  void allocate(Eigen::Index n) {
    if (size_ == n) return;
    size_ = n;
#ifdef DDB_USE_LAPACK
    pivots_.assign(static_cast<std::size_t>(n), 0);
    // ?getri's workspace: the size it asks for in a query (lwork = −1).
    Matrix probe = Matrix::Identity(n, n);
    const auto m = static_cast<lapack_int>(n);
    Scalar optimal = 0;
    if constexpr (std::is_same_v<Scalar, double>) {
      LAPACKE_dgetri_work(LAPACK_COL_MAJOR, m, probe.data(), m, pivots_.data(), &optimal, -1);
    } else {
      LAPACKE_zgetri_work(LAPACK_COL_MAJOR, m, lapackData(probe.data()), m, pivots_.data(),
                          lapackData(&optimal), -1);
    }
    work_.assign(static_cast<std::size_t>(std::max(std::real(optimal), double(n))), Scalar(0));
#else
    lu_ = Eigen::PartialPivLU<Matrix>(n);
    identity_ = Matrix::Identity(n, n);
#endif
  }

  Eigen::Index size_ = -1;
#ifdef DDB_USE_LAPACK
  std::vector<lapack_int> pivots_;
  std::vector<Scalar> work_;
#else
  Eigen::PartialPivLU<Matrix> lu_;
  Matrix identity_;
#endif
};

}  // namespace ddb
