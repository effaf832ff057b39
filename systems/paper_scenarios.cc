// The paper's scenarios (systems/paper_scenarios.h), compiled once into the library.
#include <ddb/systems/paper_scenarios.h>

namespace ddb {

const std::vector<RigidBodyScenario>& rigidBodyScenarios() {
  static const std::vector<RigidBodyScenario> scenarios{
      {"A", "asymmetric body (1, 1.3, 0.5), t in [0, 30]: Casimir, error vs h, runtime table",
       Eigen::Vector3d(1.0, 1.3, 0.5), 0.5, Eigen::Vector3d(0.0, 0.05, 1.0), 30.0},
      {"B", "as A over t in [0, 250]: convergence to the limit points +-|M0| e2",
       Eigen::Vector3d(1.0, 1.3, 0.5), 0.5, Eigen::Vector3d(0.0, 0.05, 1.0), 250.0},
      {"C", "symmetric body (1, 1, 0.5), t in [0, 250]: convergence to the great circle M3 = 0",
       Eigen::Vector3d(1.0, 1.0, 0.5), 0.5, Eigen::Vector3d(0.0, 0.05, 1.0), 250.0}};
  return scenarios;
}

const RigidBodyScenario& rigidBodyScenario(const std::string& name) {
  std::string valid;
  for (const auto& s : rigidBodyScenarios()) {
    if (s.name == name) return s;
    valid += (valid.empty() ? "" : ", ") + s.name;
  }
  throwInvalid("scenario", name, "expected one of " + valid);
}

}  // namespace ddb
