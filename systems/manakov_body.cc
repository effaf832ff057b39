// The Manakov body's constructor (systems/manakov_body.h), compiled once into the library.
#include <ddb/systems/manakov_body.h>

namespace ddb {

std::shared_ptr<const LiePoissonSystem<SON>> makeManakovBody(const Eigen::VectorXd& J,
                                                             double alpha) {
  return makeLiePoissonSystem("manakov-body", std::make_shared<const ManakovHamiltonian>(J),
                              std::make_shared<const ScaledIdentityMetric<SON>>(alpha));
}

}  // namespace ddb
