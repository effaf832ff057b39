// How far SU(N) ⋉ su(N)*'s Casimirs (DualNumberSUN::casimirs: tr Θᵏ, k = 2 … N, then tr(ΘᵏW),
// k = 0 … N − 1) moved from μ0's, each against its scale from μ0: |tr Θᵏ| ≤ N‖Θ‖₂ᵏ and
// |tr(ΘᵏW)| ≤ N‖Θ‖₂ᵏ‖W‖₂ (‖·‖₂ the largest singular value, Eigen's SVD). The magnetic fluid's
// tests on every backend compare this with 1e-12.
#pragma once

#include <ddb/core/dual_matrix.h>
#include <ddb/groups/dual_number_sun.h>

#include <Eigen/SVD>
#include <cmath>

namespace ddb::test {

/// max over the Casimirs of |c(μ) − c(μ0)| / scale(μ0).
inline double mhdCasimirDrift(const DualMatrix<Eigen::MatrixXcd>& mu0,
                              const DualMatrix<Eigen::MatrixXcd>& mu) {
  const Eigen::Index n = mu0.real.rows();
  const double theta = Eigen::JacobiSVD<Eigen::MatrixXcd>(mu0.real).singularValues()(0);
  const double w = Eigen::JacobiSVD<Eigen::MatrixXcd>(mu0.eps).singularValues()(0);
  const Eigen::VectorXd c0 = DualNumberSUN::casimirs(mu0), c = DualNumberSUN::casimirs(mu);
  Eigen::VectorXd scale(c0.size());
  for (Eigen::Index k = 0; k < n; ++k) {
    if (k + 2 <= n) scale(k) = double(n) * std::pow(theta, double(k + 2));
    scale(n - 1 + k) = double(n) * std::pow(theta, double(k)) * w;
  }
  return (c - c0).cwiseAbs().cwiseQuotient(scale).maxCoeff();
}

}  // namespace ddb::test
