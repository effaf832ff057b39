// The paper's scenario data (Section 5; docs/reference/conventions.md §3) and the default heavy
// top, Kirchhoff body and planar Kirchhoff body, written once for the apps, the benchmark and the
// tests.
// Each value type holds plain data and builds its system and initial momentum on demand,
// so that a caller can start from a scenario and override single parameters.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/kirchhoff.h>
#include <ddb/systems/planar_kirchhoff.h>
#include <ddb/systems/rigid_body.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace ddb {

/// Rigid body with k♯ = α I, started from M₀ = 𝕀Ω₀ (paper, Section 5).
struct RigidBodyScenario {
  std::string name;         // "A", "B", "C"
  std::string description;  // one line, for --help
  Eigen::Vector3d inertia;  // principal moments 𝕀
  double alpha;             // dissipation scale
  Eigen::Vector3d omega0;   // initial angular velocity Ω₀
  double t_end;             // the paper's horizon

  Eigen::Vector3d mu0() const { return inertia.cwiseProduct(omega0); }
  std::shared_ptr<const LiePoissonSystem<SO3>> system() const {
    return makeRigidBody(inertia, alpha);
  }
  bool sameParameters(const RigidBodyScenario& other) const {
    return inertia == other.inertia && alpha == other.alpha && omega0 == other.omega0;
  }
};

/// Scenarios A, B and C in the paper's order.
const std::vector<RigidBodyScenario>& rigidBodyScenarios();

/// The scenario called `name`; an unknown name is an InvalidArgument listing the valid ones.
const RigidBodyScenario& rigidBodyScenario(const std::string& name);

using Vector6d = Eigen::Matrix<double, 6, 1>;

/// Heavy top with k♯ = α diag(metric); μ₀ = (π, γ) with γ tilted by 0.3 rad from e3.
struct HeavyTopSetup {
  Eigen::Vector3d inertia = Eigen::Vector3d(1.0, 1.3, 0.5);
  double mgl = 1.0;
  Eigen::Vector3d chi = Eigen::Vector3d(0.0, 0.0, 1.0);
  Vector6d mu0 = (Vector6d() << 0.0, 0.065, 0.5, 0.0, std::sin(0.3), std::cos(0.3)).finished();
  Vector6d metric = Vector6d::Ones();
  double alpha = 0.5;
  double t_end = 30.0;

  std::shared_ptr<const LiePoissonSystem<SE3>> system() const {
    return makeHeavyTop(inertia, mgl, chi, alpha, metric);
  }
  bool sameParameters(const HeavyTopSetup& o) const {
    return inertia == o.inertia && mgl == o.mgl && chi == o.chi && mu0 == o.mu0 &&
           metric == o.metric && alpha == o.alpha;
  }
};

/// Kirchhoff body (added masses 𝕄) with k♯ = α diag(metric).
struct KirchhoffSetup {
  Eigen::Vector3d inertia = Eigen::Vector3d(1.0, 1.3, 0.5);
  Eigen::Vector3d mass = Eigen::Vector3d(1.0, 2.0, 3.0);
  Vector6d mu0 = (Vector6d() << 0.0, 0.065, 0.5, 1.0, 0.0, 0.2).finished();
  Vector6d metric = Vector6d::Ones();
  double alpha = 0.5;
  double t_end = 30.0;

  std::shared_ptr<const LiePoissonSystem<SE3>> system() const {
    return makeKirchhoffBody(inertia, mass, alpha, metric);
  }
  bool sameParameters(const KirchhoffSetup& o) const {
    return inertia == o.inertia && mass == o.mass && mu0 == o.mu0 && metric == o.metric &&
           alpha == o.alpha;
  }
};

/// Kirchhoff's planar body (moment of inertia I, added masses (m₁, m₂)) with k♯ = α diag(metric):
/// from μ₀ it relaxes to the energy's minimum on its orbit |P| = |P₀|, c²/(2 max m)
/// (docs/guide/defining-a-system.md, "A group made of groups").
struct PlanarKirchhoffSetup {
  double inertia = 0.5;
  Eigen::Vector2d mass = Eigen::Vector2d(1.0, 3.0);
  Eigen::Vector3d mu0 = Eigen::Vector3d(0.3, 1.0, 0.2);
  Eigen::Vector3d metric = Eigen::Vector3d::Ones();
  double alpha = 0.5;
  double t_end = 30.0;

  std::shared_ptr<const LiePoissonSystem<SE2>> system() const {
    return makePlanarKirchhoffBody(inertia, mass, alpha, metric);
  }
  bool sameParameters(const PlanarKirchhoffSetup& o) const {
    return inertia == o.inertia && mass == o.mass && mu0 == o.mu0 && metric == o.metric &&
           alpha == o.alpha;
  }
};

}  // namespace ddb
