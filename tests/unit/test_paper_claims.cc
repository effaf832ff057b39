// The paper's Section 5 claims on its own scenarios (docs/reference/conventions.md §3), at h = 0.1:
// A: DDB keeps the Casimir to round-off while RK4 and Lobatto IIIC drift;
// B: DDB ends closer to the limit point and to the reference than RK4;
// C: DDB ends on the sphere |M| = |M0| to round-off and converges to the great circle.
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>

#include "test_support.h"

namespace ddb::test {
namespace paper_claims_tests {

using Scenario = RigidBodyScenario;
const Scenario& kA = rigidBodyScenario("A");
const Scenario& kB = rigidBodyScenario("B");
const Scenario& kC = rigidBodyScenario("C");

struct Outcome {
  Eigen::Vector3d final;
  double casimir_drift = 0.0;
};

Outcome run(const std::string& method, const Scenario& s) {
  auto integrator = makeMethod<SO3>(method, s.system());
  const Eigen::Vector3d m0 = s.mu0();
  Outcome out;
  integrate(*integrator, m0, 0.0, 0.1, std::lround(s.t_end / 0.1),
            [&](long, double, const Eigen::Vector3d& mu) {
              out.final = mu;
              out.casimir_drift =
                  std::max(out.casimir_drift, std::abs(mu.norm() - m0.norm()) / m0.norm());
            });
  return out;
}

TEST(PaperClaims, ScenarioADdbKeepsTheCasimirOthersDrift) {
  for (const std::string m : {"ddb-cay", "ddb-exp", "ddb-exp-exact"}) {
    EXPECT_LE(run(m, kA).casimir_drift, 1e-14) << m;
  }
  EXPECT_GT(run("rk4", kA).casimir_drift, 1e-9);
  EXPECT_GT(run("lobatto3c", kA).casimir_drift, 1e-11);
}

TEST(PaperClaims, ScenarioBDdbEndsCloserThanRk4) {
  const Eigen::Vector3d m0 = kB.mu0();
  // Minimum energy on the sphere: ±|M0| e2 (largest moment of inertia).
  const auto toLimit = [&](const Eigen::Vector3d& m) {
    const Eigen::Vector3d e = m0.norm() * Eigen::Vector3d::UnitY();
    return std::min((m - e).norm(), (m + e).norm());
  };
  const Eigen::Vector3d reference = run("reference", kB).final;
  const Outcome rk4 = run("rk4", kB);
  for (const std::string m : {"ddb-cay", "ddb-exp"}) {
    const Outcome ddb = run(m, kB);
    EXPECT_LT(toLimit(ddb.final), toLimit(rk4.final)) << m;
    EXPECT_LT((ddb.final - reference).norm(), (rk4.final - reference).norm()) << m;
  }
}

TEST(PaperClaims, ScenarioCDdbEndsOnTheGreatCircle) {
  const Eigen::Vector3d m0 = kC.mu0();
  const Eigen::Vector3d reference = run("reference", kC).final;
  for (const std::string m : {"ddb-cay", "ddb-exp"}) {
    const Eigen::Vector3d M = run(m, kC).final;
    // Radial part: round-off. Distance to the plane M3 = 0: as small as the exact flow's.
    EXPECT_LT(std::abs(M.norm() - m0.norm()), 1e-14) << m;
    EXPECT_LT(std::abs(M(2)), 10 * std::abs(reference(2)) + 1e-15) << m;
  }
  // RK4 converges to a circle of the wrong radius.
  const Eigen::Vector3d rk4 = run("rk4", kC).final;
  EXPECT_GT(std::abs(rk4.norm() - m0.norm()), 1e-10);
}

}  // namespace paper_claims_tests
}  // namespace ddb::test
