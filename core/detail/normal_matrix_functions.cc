#include <ddb/core/detail/normal_matrix_functions.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <complex>

namespace ddb::detail {
namespace {

template <class Complex>
double sumOfTwoLargestEigenvaluesOfMinusI(const Eigen::Ref<const Eigen::MatrixXd>& X) {
  const Complex H = X.cast<std::complex<double>>() * std::complex<double>(0.0, -1.0);
  const Eigen::SelfAdjointEigenSolver<Complex> eigen(H, Eigen::EigenvaluesOnly);
  const auto& lambda = eigen.eigenvalues();  // ascending
  const Eigen::Index n = X.rows();
  return std::max(0.0, lambda(n - 1) + lambda(n - 2));
}

// The largest n whose eigensolver works without the heap: a 16×16 complex matrix is 4 KiB.
constexpr int kInlineSize = 16;

}  // namespace

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

double skewSymmetricAdRadius(const Eigen::Ref<const Eigen::MatrixXd>& X) {
  using InlineComplex = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic,
                                      Eigen::ColMajor, kInlineSize, kInlineSize>;
  return X.rows() <= kInlineSize ? sumOfTwoLargestEigenvaluesOfMinusI<InlineComplex>(X)
                                 : sumOfTwoLargestEigenvaluesOfMinusI<Eigen::MatrixXcd>(X);
}

}  // namespace ddb::detail
