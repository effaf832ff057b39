// SO(N) and SU(N) against the SO3 group through explicit isomorphisms
// (docs/reference/conventions.md §2).
#include <ddb/groups/so3.h>
#include <ddb/groups/son.h>
#include <ddb/groups/sun.h>
#include <gtest/gtest.h>

#include <complex>

#include "test_support.h"

namespace ddb::test {
namespace matrix_groups_tests {

// so(3) ≅ R³ by hat; the matrix pairing is twice the dot product.
TEST(SON, So3IsR3ThroughHat) {
  Sampler s(31);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d x = 2 * s.vector<Eigen::Vector3d>(), y = s.vector<Eigen::Vector3d>(),
                          mu = s.vector<Eigen::Vector3d>();
    const Eigen::MatrixXd X = SO3::hat(x), Y = SO3::hat(y), M = SO3::hat(mu);
    EXPECT_LT((SON::bracket(X, Y) - Eigen::MatrixXd(SO3::hat(SO3::bracket(x, y)))).norm(), 1e-14);
    EXPECT_LT((SON::adDual(X, M) - Eigen::MatrixXd(SO3::hat(SO3::adDual(x, mu)))).norm(), 1e-14);
    EXPECT_NEAR(SON::pairing(M, X), 2 * SO3::pairing(mu, x), 1e-14);
    const Eigen::MatrixXd R = SON::exp(X);
    EXPECT_LT((R - Eigen::MatrixXd(SO3::exp(x))).norm(), 1e-14);
    EXPECT_LT((SON::AdDual(R, M) - Eigen::MatrixXd(SO3::hat(SO3::AdDual(SO3::exp(x), mu)))).norm(),
              1e-14);
    EXPECT_LT((SON::cay(X) - Eigen::MatrixXd(SO3::cay(x))).norm(), 1e-14);
    EXPECT_LT((SON::dcayInvDual(X, M) - Eigen::MatrixXd(SO3::hat(SO3::dcayInvDual(x, mu)))).norm(),
              1e-14);
    // Spectrum of a real skew 3×3 matrix: (−|μ|, 0, |μ|).
    const Eigen::VectorXd spectrum = SON::casimirs(M);
    EXPECT_LT((spectrum - Eigen::Vector3d(-mu.norm(), 0, mu.norm())).norm(), 1e-14);
  }
}

// su(2) ≅ so(3) by ρ(x) = −(i/2) x·σ (Pauli matrices): [ρ(x), ρ(y)] = ρ(x × y); the
// pairing is half the dot product; exp(ρ(x)) acts on su(2) as SO3::exp(x) on R³.
Eigen::MatrixXcd rho(const Eigen::Vector3d& x) {
  using C = std::complex<double>;
  Eigen::Matrix2cd m;
  m << C(0, -x(2)), C(-x(1), -x(0)), C(x(1), -x(0)), C(0, x(2));
  return 0.5 * m;
}

TEST(SUN, Su2IsSo3ThroughPauliMatrices) {
  Sampler s(32);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d x = 2 * s.vector<Eigen::Vector3d>(), y = s.vector<Eigen::Vector3d>(),
                          mu = s.vector<Eigen::Vector3d>();
    EXPECT_LT((rho(x) + rho(x).adjoint()).norm(), 1e-15);
    EXPECT_LT((SUN::bracket(rho(x), rho(y)) - rho(x.cross(y))).norm(), 1e-14);
    EXPECT_LT((SUN::adDual(rho(x), rho(mu)) - rho(SO3::adDual(x, mu))).norm(), 1e-14);
    EXPECT_NEAR(SUN::pairing(rho(mu), rho(x)), 0.5 * mu.dot(x), 1e-14);
    const Eigen::MatrixXcd g = SUN::exp(rho(x));
    EXPECT_NEAR(std::abs(g.determinant() - 1.0), 0.0, 1e-14);
    EXPECT_LT((SUN::Ad(g, rho(y)) - rho(SO3::exp(x) * y)).norm(), 1e-14);
    EXPECT_LT((SUN::AdDual(g, rho(mu)) - rho(SO3::AdDual(SO3::exp(x), mu))).norm(), 1e-14);
    // Spectrum of −iρ(μ) = −(1/2) μ·σ: ±|μ|/2.
    EXPECT_LT((SUN::casimirs(rho(mu)) - Eigen::Vector2d(-mu.norm() / 2, mu.norm() / 2)).norm(),
              1e-14);
  }
}

}  // namespace matrix_groups_tests
}  // namespace ddb::test
