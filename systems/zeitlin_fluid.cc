// Zeitlin's fluid's constructor (systems/zeitlin_fluid.h), compiled once into the library.
#include <ddb/systems/zeitlin_fluid.h>

namespace ddb {

std::shared_ptr<const LiePoissonSystem<SUN>> makeZeitlinFluid(Eigen::Index n, double alpha) {
  return makeZeitlinFluid(n, alpha, ZeitlinPhysics{});
}

std::shared_ptr<const LiePoissonSystem<SUN>> makeZeitlinFluid(Eigen::Index n, double alpha,
                                                              const ZeitlinPhysics& physics) {
  return makeLiePoissonSystem("zeitlin", std::make_shared<const ZeitlinHamiltonian>(n, physics),
                              std::make_shared<const ScaledIdentityMetric<SUN>>(alpha));
}

}  // namespace ddb
