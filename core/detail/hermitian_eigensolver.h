// HermitianEigensolver: the eigenvalues (ascending) and orthonormal eigenvectors of a complex
// Hermitian matrix, with its workspace allocated when a size first appears, then reused (no
// allocation per call). The exponential retraction of the matrix groups decomposes one or
// two skew-Hermitian matrices per sweep and step (docs/reference/conventions.md §1, "Matrix
// algebras"). With DDB_USE_LAPACK it calls ?heevd (divide and conquer) through LAPACKE's
// _work variant (core/detail/lapack.h); the fallback is Eigen's SelfAdjointEigenSolver, whose
// Householder back-transformation allocates on every call.
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
    return lapack::heevd(static_cast<lapack::Int>(A.rows()), vectors_.data(), values_.data(),
                         work_.data(), static_cast<lapack::Int>(work_.size()), rwork_.data(),
                         static_cast<lapack::Int>(rwork_.size()), iwork_.data(),
                         static_cast<lapack::Int>(iwork_.size())) == 0;
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
    std::complex<double> work = 0;
    double rwork = 0;
    lapack::Int iwork = 0;
    lapack::heevd(static_cast<lapack::Int>(n), vectors_.data(), values_.data(), &work, -1, &rwork,
                  -1, &iwork, -1);
    work_.assign(static_cast<std::size_t>(std::max(std::real(work), 1.0)), 0.0);
    rwork_.assign(static_cast<std::size_t>(std::max(rwork, 1.0)), 0.0);
    iwork_.assign(static_cast<std::size_t>(std::max<lapack::Int>(iwork, 1)), 0);
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
  std::vector<lapack::Int> iwork_;
#else
  Eigen::SelfAdjointEigenSolver<Matrix> eigen_;
#endif
};

}  // namespace ddb
