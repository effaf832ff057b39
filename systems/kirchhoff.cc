// Kirchhoff's body's constructor (systems/kirchhoff.h), compiled once into the library.
#include <ddb/systems/kirchhoff.h>

namespace ddb {

std::shared_ptr<const LiePoissonSystem<SE3>> makeKirchhoffBody(
    const Eigen::Vector3d& inertia, const Eigen::Vector3d& mass, double alpha,
    const Eigen::Matrix<double, 6, 1>& metric) {
  return makeKirchhoffBodyOn<SE3>(inertia, mass, alpha, metric);
}

}  // namespace ddb
