// The heavy top's constructor (systems/heavy_top.h), compiled once into the library.
#include <ddb/systems/heavy_top.h>

namespace ddb {

std::shared_ptr<const LiePoissonSystem<SE3>> makeHeavyTop(
    const Eigen::Vector3d& inertia, double mgl, const Eigen::Vector3d& chi, double alpha,
    const Eigen::Matrix<double, 6, 1>& metric) {
  return makeHeavyTopOn<SE3>(inertia, mgl, chi, alpha, metric);
}

}  // namespace ddb
