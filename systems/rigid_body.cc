// The rigid body's constructors (systems/rigid_body.h), compiled once into the library.
#include <ddb/systems/rigid_body.h>

namespace ddb {

std::shared_ptr<const LiePoissonSystem<SO3>> makeRigidBody(const Eigen::Vector3d& inertia,
                                                           double alpha) {
  return makeLiePoissonSystem("rigid-body", std::make_shared<const RigidBodyHamiltonian>(inertia),
                              std::make_shared<const ScaledIdentityMetric<SO3>>(alpha),
                              std::make_shared<const RigidBodyLagrangian>(inertia));
}

}  // namespace ddb
