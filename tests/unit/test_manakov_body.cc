// The SO(N) generalised rigid body (Manakov) against the SO3 rigid body
// (docs/reference/conventions.md §2), and its refusal of bad principal values.
#include <ddb/core/errors.h>
#include <ddb/groups/cayley.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/rigid_body.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace ddb::test {
namespace manakov_body_tests {

// The Manakov body at N = 3 is the rigid body with 𝕀 = (J₂+J₃, J₁+J₃, J₁+J₂): 1000 DDB
// Cayley steps (Hamiltonian form on both sides) agree to 1e-12.
TEST(ManakovBody, AtN3ReproducesTheRigidBody) {
  const Eigen::Vector3d J(0.2, 0.45, 0.7);
  const Eigen::Vector3d inertia(J(1) + J(2), J(0) + J(2), J(0) + J(1));
  for (double alpha : {0.0, 0.5}) {
    Ddb<Cayley<SO3>> body(makeRigidBody(inertia, alpha), Cayley<SO3>(), LegendreForm::kHamiltonian);
    Ddb<Cayley<SON>> manakov(makeManakovBody(J, alpha), Cayley<SON>(), LegendreForm::kHamiltonian);
    Eigen::Vector3d m = inertia.cwiseProduct(Eigen::Vector3d(0, 0.05, 1));
    Eigen::MatrixXd M = SO3::hat(m);
    double worst = 0.0;
    for (int k = 0; k < 1000; ++k) {
      m = body.step(m, 0.1 * k, 0.1);
      M = manakov.step(M, 0.1 * k, 0.1);
      worst = std::max(worst, (M - Eigen::MatrixXd(SO3::hat(m))).norm() / M.norm());
    }
    EXPECT_LT(worst, 1e-12) << "alpha " << alpha;
  }
}

TEST(ManakovBody, RejectsBadPrincipalValues) {
  EXPECT_THROW(makeManakovBody(Eigen::Vector3d(1, -1, 2), 0.1), InvalidArgument);
  EXPECT_THROW(makeManakovBody(Eigen::VectorXd::Ones(1), 0.1), InvalidArgument);
  EXPECT_THROW(makeManakovBody(Eigen::Vector3d(1, NAN, 2), 0.1), InvalidArgument);
}

}  // namespace manakov_body_tests
}  // namespace ddb::test
