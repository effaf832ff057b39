#include <ddb/core/detail/normal_matrix_functions.h>

#include <Eigen/Eigenvalues>
#include <complex>

namespace ddb::detail {

Eigen::VectorXd hermitianEigenvalues(const Eigen::MatrixXcd& A) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> eigen(A, Eigen::EigenvaluesOnly);
  return eigen.eigenvalues();
}

Eigen::MatrixXcd unitaryLogarithm(const Eigen::MatrixXcd& U) {
  const Eigen::ComplexSchur<Eigen::MatrixXcd> schur(U);
  const Eigen::MatrixXcd& V = schur.matrixU();
  const Eigen::VectorXcd logs = schur.matrixT().diagonal().unaryExpr(
      [](const std::complex<double>& l) { return std::complex<double>(0, std::arg(l)); });
  return V * logs.asDiagonal() * V.adjoint();
}

}  // namespace ddb::detail
