// A new system in ddb, defined by its reduced Lagrangian alone: a body on SO(3) whose
// kinetic energy stiffens at high spin,
//   l(Ω) = ½ Ω·𝕀Ω + (β/4)|Ω|⁴,
// damped by the double bracket with a diagonal metric k♯ = α diag(k). The program
// integrates it with DDB (Cayley retraction) and with classical RK4 and prints the
// energy and Casimir drift of each. It is also a check: it exits with status 1 if
// DDB moves the Casimir |M| by more than 1e-12 (relative) or the energy ever rises
// (α > 0 makes it decay).
#include <ddb/ddb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace {

// AutoDiffLagrangian supplies ∂l/∂Ω and the Hessian action from this one templated
// `evaluate`, using ceres::Jet for T (nested Jets for second derivatives). Nested Jets
// cannot be built from a double, so every constant goes through ddb::constant<T>.
class StiffeningBody : public ddb::AutoDiffLagrangian<StiffeningBody, ddb::SO3> {
 public:
  // β >= 0 keeps l strictly convex, so its Legendre transform is invertible.
  StiffeningBody(const Eigen::Vector3d& inertia, double beta)
      : inertia_(ddb::requirePositive("inertia", inertia)),
        beta_(ddb::requireFinite("beta", beta)) {
    if (beta_ < 0) ddb::throwInvalid("beta", ddb::formatValue(beta_), "must be >= 0");
  }

  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& omega) const {
    T quadratic = ddb::constant<T>(0.0), norm2 = ddb::constant<T>(0.0);
    for (int i = 0; i < 3; ++i) {
      quadratic += ddb::constant<T>(inertia_(i)) * omega(i) * omega(i);
      norm2 += omega(i) * omega(i);
    }
    return ddb::constant<T>(0.5) * quadratic + ddb::constant<T>(0.25 * beta_) * norm2 * norm2;
  }

 private:
  Eigen::Vector3d inertia_;
  double beta_;
};

struct Drift {
  double energy_change;  // E(T) − E(0)
  double casimir_drift;  // max over the trajectory of |C(t) − C(0)| / |C(0)|
  bool energy_rose;      // E(t_{k+1}) > E(t_k) at some step, beyond round-off
};

// Runs `method` and watches every state through the observer of ddb::integrate.
Drift measure(ddb::OneStepMethod<ddb::SO3>& method, const ddb::LiePoissonSystem<ddb::SO3>& system,
              const Eigen::Vector3d& m0, double h, long steps) {
  const double e0 = system.energy(m0), c0 = system.casimirs(m0)(0);
  Drift drift{0.0, 0.0, false};
  double previous = e0;
  ddb::integrate(method, m0, 0.0, h, steps, [&](long, double, const Eigen::Vector3d& m) {
    const double e = system.energy(m);
    // The energy (a Legendre transform solved to 1e-14) carries round-off of that size.
    drift.energy_rose |= e > previous + 1e-13 * std::abs(e0);
    previous = e;
    drift.energy_change = e - e0;
    drift.casimir_drift = std::max(drift.casimir_drift, std::abs(system.casimirs(m)(0) - c0) / c0);
  });
  return drift;
}

}  // namespace

int main() {
  const Eigen::Vector3d inertia(1.0, 1.3, 0.5);
  const double beta = 0.2, alpha = 0.5;
  const auto lagrangian = std::make_shared<const StiffeningBody>(inertia, beta);
  const auto metric =
      std::make_shared<const ddb::DiagonalMetric<ddb::SO3>>(alpha, Eigen::Vector3d(1.0, 2.0, 0.5));
  // The Hamiltonian comes from the Lagrangian by the inverse Legendre transform.
  const auto system =
      ddb::makeSystemFromLagrangian<ddb::SO3>("stiffening-body", lagrangian, metric);

  // Start from the paper's angular velocity; the momentum is M = ∂l/∂Ω.
  const Eigen::Vector3d m0 = lagrangian->gradient(Eigen::Vector3d(0.0, 0.05, 1.0));
  const double h = 0.1;
  const long steps = 300;  // t ∈ [0, 30]

  ddb::Ddb<ddb::Cayley<ddb::SO3>> ddb_cay(system);
  ddb::ExplicitRungeKutta<ddb::SO3, 4> rk4(system, ddb::kClassicalRk4);
  const Drift ddb = measure(ddb_cay, *system, m0, h, steps);
  const Drift peer = measure(rk4, *system, m0, h, steps);

  std::printf("E(0) = %.15e, |M0| = %.15e, t in [0, %g]\n", system->energy(m0), m0.norm(),
              steps * h);
  std::printf("%-8s %22s %24s\n", "method", "E(T) - E(0)", "max rel. Casimir drift");
  std::printf("%-8s %22.15e %24.3e\n", "ddb-cay", ddb.energy_change, ddb.casimir_drift);
  std::printf("%-8s %22.15e %24.3e\n", "rk4", peer.energy_change, peer.casimir_drift);

  const bool ok = ddb.casimir_drift <= 1e-12 && !ddb.energy_rose;
  if (!ok) std::fprintf(stderr, "FAILED: DDB left the coadjoint orbit or gained energy\n");
  return ok ? 0 : 1;
}
