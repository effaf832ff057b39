// DenseInverse: A ← A⁻¹ in place for a square dynamic-size matrix (real or complex), with
// its pivots and workspace allocated when a size first appears, then reused (no
// allocation per call). The Cayley transport of the matrix groups inverts I − x once or
// twice per step (docs/conventions.md §4). With DDB_USE_LAPACK (set by the build when a
// LAPACK is found next to the BLAS) it calls ?getrf + ?getri: with Debian's OpenBLAS that is
// 1.4 complex N×N products at N = 256, against 3.0 for Eigen's own LU and solve against the
// identity, which is the fallback (docs/design.md, "Measured, and what it decided").
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <complex>
#include <type_traits>
#include <vector>

#ifdef DDB_USE_LAPACK
extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetri_(const int* n, double* a, const int* lda, const int* ipiv, double* work,
             const int* lwork, int* info);
void zgetrf_(const int* m, const int* n, std::complex<double>* a, const int* lda, int* ipiv,
             int* info);
void zgetri_(const int* n, std::complex<double>* a, const int* lda, const int* ipiv,
             std::complex<double>* work, const int* lwork, int* info);
}
#endif

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
    const int n = static_cast<int>(A.rows());
    const int lwork = static_cast<int>(work_.size());
    int info = 0;
    if constexpr (std::is_same_v<Scalar, double>) {
      dgetrf_(&n, &n, A.data(), &n, pivots_.data(), &info);
      if (info != 0) return false;
      dgetri_(&n, A.data(), &n, pivots_.data(), work_.data(), &lwork, &info);
    } else {
      zgetrf_(&n, &n, A.data(), &n, pivots_.data(), &info);
      if (info != 0) return false;
      zgetri_(&n, A.data(), &n, pivots_.data(), work_.data(), &lwork, &info);
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
    const int m = static_cast<int>(n), query = -1;
    int info = 0;
    Scalar optimal = 0;
    if constexpr (std::is_same_v<Scalar, double>) {
      dgetri_(&m, probe.data(), &m, pivots_.data(), &optimal, &query, &info);
    } else {
      zgetri_(&m, probe.data(), &m, pivots_.data(), &optimal, &query, &info);
    }
    work_.assign(static_cast<std::size_t>(std::max(std::real(optimal), double(n))), Scalar(0));
#else
    lu_ = Eigen::PartialPivLU<Matrix>(n);
    identity_ = Matrix::Identity(n, n);
#endif
  }

  Eigen::Index size_ = -1;
#ifdef DDB_USE_LAPACK
  std::vector<int> pivots_;
  std::vector<Scalar> work_;
#else
  Eigen::PartialPivLU<Matrix> lu_;
  Matrix identity_;
#endif
};

}  // namespace ddb
