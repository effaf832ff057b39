// integrate() and Trajectory through the header 0.2.0's guide named for them,
// <ddb/integrators/methods/one_step_method.h>, alone (CHANGELOG.md, 0.3.0, "Deprecated"; until
// 0.4.0): a program that included only it still compiles. No main(): the compile is the test.
#include <ddb/groups/so3.h>
#include <ddb/integrators/methods/one_step_method.h>

namespace {

[[maybe_unused]] void integrateThroughTheOldHeader(ddb::OneStepMethod<ddb::SO3>& method) {
  ddb::Trajectory<ddb::SO3> trajectory;
  ddb::integrate(method, Eigen::Vector3d(1.0, 0.0, 0.0), 0.0, 0.1, 2, trajectory.record());
}

}  // namespace
