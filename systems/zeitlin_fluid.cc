// Zeitlin's fluid's constructor (systems/zeitlin_fluid.h), compiled once into the library.
#include <ddb/systems/zeitlin_fluid.h>

namespace ddb {

std::shared_ptr<const LiePoissonSystem<SUN>> makeZeitlinFluid(Eigen::Index n, double alpha) {
  return makeLiePoissonSystem("zeitlin", std::make_shared<const ZeitlinHamiltonian>(n),
                              std::make_shared<const ScaledIdentityMetric<SUN>>(alpha));
}

}  // namespace ddb
