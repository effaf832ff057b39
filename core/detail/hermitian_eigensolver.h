// HermitianEigensolver: the eigenvalues (ascending) and orthonormal eigenvectors of a complex
// Hermitian matrix, with its workspace allocated when a size first appears, then reused (no
// allocation per call). The exponential retraction of the matrix groups decomposes one or
// two skew-Hermitian matrices per sweep and step (docs/reference/conventions.md §1, "Matrix
// algebras"). With DDB_USE_LAPACK it calls ?heevd (divide and conquer) through LAPACKE's
// _work variant; the fallback is Eigen's SelfAdjointEigenSolver, whose Householder
// back-transformation allocates on every call.
#pragma once

#include <ddb/core/detail/lapack.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <complex>
#include <vector>

namespace ddb {

class HermitianEigensolver {
 public:
  using Matrix = Eigen::MatrixXcd;

  /// Decomposes the Hermitian A (its lower triangle is read). Returns false when the
  /// iteration did not converge (A not finite); the results are then unspecified.
  bool compute(const Matrix& A) {
    allocate(A.rows());
    vectors_ = A;
#ifdef DDB_USE_LAPACK
    const auto n = static_cast<lapack_int>(A.rows());
    const lapack_int info = LAPACKE_zheevd_work(
        LAPACK_COL_MAJOR, 'V', 'L', n, lapackData(vectors_.data()), n, values_.data(),
        lapackData(work_.data()), static_cast<lapack_int>(work_.size()), rwork_.data(),
        static_cast<lapack_int>(rwork_.size()), iwork_.data(),
        static_cast<lapack_int>(iwork_.size()));
    return info == 0;
#else
    eigen_.compute(vectors_);
    if (eigen_.info() != Eigen::Success) return false;
    vectors_ = eigen_.eigenvectors();
    values_ = eigen_.eigenvalues();
    return true;
#endif
  }

  const Eigen::VectorXd& eigenvalues() const { return values_; }
  const Matrix& eigenvectors() const { return vectors_; }

 private:
  void allocate(Eigen::Index n) {
    if (size_ == n) return;
    size_ = n;
    values_.setZero(n);
    vectors_.setZero(n, n);
#ifdef DDB_USE_LAPACK
    // The sizes ?heevd asks for in a workspace query (lwork = lrwork = liwork = −1).
    const auto m = static_cast<lapack_int>(n);
    std::complex<double> work = 0;
    double rwork = 0;
    lapack_int iwork = 0;
    LAPACKE_zheevd_work(LAPACK_COL_MAJOR, 'V', 'L', m, lapackData(vectors_.data()), m,
                        values_.data(), lapackData(&work), -1, &rwork, -1, &iwork, -1);
    work_.assign(static_cast<std::size_t>(std::max(std::real(work), 1.0)), 0.0);
    rwork_.assign(static_cast<std::size_t>(std::max(rwork, 1.0)), 0.0);
    iwork_.assign(static_cast<std::size_t>(std::max<lapack_int>(iwork, 1)), 0);
#else
    eigen_ = Eigen::SelfAdjointEigenSolver<Matrix>(n);
#endif
  }

  Eigen::Index size_ = -1;
  Eigen::VectorXd values_;
  Matrix vectors_;
#ifdef DDB_USE_LAPACK
  std::vector<std::complex<double>> work_;
  std::vector<double> rwork_;
  std::vector<lapack_int> iwork_;
#else
  Eigen::SelfAdjointEigenSolver<Matrix> eigen_;
#endif
};

}  // namespace ddb
