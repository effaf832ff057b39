// The damping and forcing of Zeitlin's fluid as exact flows, in the one order in which every
// caller Strang-splits them around a method of the table (fluid-relax's run, ddb.zeitlin's
// integrate): the viscous flow innermost, then the stochastic forcing, then the fixed forcing
// (docs/guide/matrix-groups-and-the-fluid.md, "Viscosity, hyperviscosity and drag", "Forcing").
#pragma once

#include <ddb/core/exact_flow.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_forcing.h>
#include <ddb/systems/zeitlin_viscosity.h>

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace ddb {

/// What damps and forces a fluid: ν, p, γ; a band-limited stochastic forcing; a fixed forcing Φ
/// (empty: none).
struct ZeitlinDampingAndForcing {
  ZeitlinViscosity viscosity;
  ZeitlinStochasticForcing forcing;
  Eigen::MatrixXcd fixed_forcing;
};

/// The flows of `d` that act on the fluid of `hamiltonian`, innermost first: a method
/// Strang-split with each in turn (StrangSplitting(method, flow)) steps the damped and forced
/// fluid. Throws InvalidArgument naming the parameter for bad ν, p, γ (whether or not they act),
/// a band or rate the fluid's N refuses, or a Φ outside su(N).
inline std::vector<std::unique_ptr<ExactFlow<SUN>>> zeitlinExactFlows(
    const ZeitlinHamiltonian& hamiltonian, const ZeitlinDampingAndForcing& d) {
  d.viscosity.validate();
  const Eigen::Index n = hamiltonian.laplacian().size();
  std::vector<std::unique_ptr<ExactFlow<SUN>>> flows;
  if (d.viscosity.damps()) {
    flows.push_back(
        std::make_unique<ZeitlinViscousFlow>(n, d.viscosity, hamiltonian.planetaryVorticity()));
  }
  if (d.forcing.forces()) {
    flows.push_back(std::make_unique<ZeitlinStochasticForcingFlow>(
        n, d.forcing, hamiltonian.laplacian().kappaSquared()));
  }
  if (d.fixed_forcing.size() > 0) {
    flows.push_back(std::make_unique<ZeitlinFixedForcingFlow>(n, d.fixed_forcing));
  }
  return flows;
}

}  // namespace ddb
