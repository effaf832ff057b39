// Kirchhoff's planar body's constructor (systems/planar_kirchhoff.h), compiled once into the
// library.
#include <ddb/systems/planar_kirchhoff.h>

namespace ddb {

std::shared_ptr<const LiePoissonSystem<SE2>> makePlanarKirchhoffBody(
    double inertia, const Eigen::Vector2d& mass, double alpha, const Eigen::Vector3d& metric) {
  return makeLiePoissonSystem("planar-kirchhoff",
                              std::make_shared<const PlanarKirchhoffHamiltonian>(inertia, mass),
                              std::make_shared<const DiagonalMetric<SE2>>(alpha, metric),
                              std::make_shared<const PlanarKirchhoffLagrangian>(inertia, mass));
}

}  // namespace ddb
