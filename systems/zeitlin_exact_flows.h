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

/// The flows of `d` that act on a fluid, innermost first, made by `make` for where its states
/// live: make.viscous(ZeitlinViscosity), make.stochastic(ZeitlinStochasticForcing) and
/// make.fixed(Φ) each return a std::unique_ptr to an ExactFlow of the states' group
/// (zeitlinExactFlows below for this process's memory; distributedZeitlinExactFlows,
/// distributed/distributed_zeitlin_exact_flows.h, for MPI ranks). A method Strang-split with each
/// in turn (StrangSplitting(method, flow)) steps the damped and forced fluid.
template <class Make>
auto zeitlinExactFlowsBy(const Make& make, const ZeitlinDampingAndForcing& d) {
  d.viscosity.validate();
  std::vector<decltype(make.viscous(d.viscosity))> flows;
  if (d.viscosity.damps()) flows.push_back(make.viscous(d.viscosity));
  if (d.forcing.forces()) flows.push_back(make.stochastic(d.forcing));
  if (d.fixed_forcing.size() > 0) flows.push_back(make.fixed(d.fixed_forcing));
  return flows;
}

/// The flows of `d` that act on the fluid of `hamiltonian`, states in this process's memory,
/// innermost first. Throws InvalidArgument naming the parameter for bad ν, p, γ (whether or not
/// they act), a band or rate the fluid's N refuses, or a Φ outside su(N).
inline std::vector<std::unique_ptr<ExactFlow<SUN>>> zeitlinExactFlows(
    const ZeitlinHamiltonian& hamiltonian, const ZeitlinDampingAndForcing& d) {
  struct Make {
    const ZeitlinHamiltonian& hamiltonian;
    Eigen::Index n() const { return hamiltonian.laplacian().size(); }
    std::unique_ptr<ExactFlow<SUN>> viscous(const ZeitlinViscosity& viscosity) const {
      return std::make_unique<ZeitlinViscousFlow>(n(), viscosity, hamiltonian.planetaryVorticity());
    }
    std::unique_ptr<ExactFlow<SUN>> stochastic(const ZeitlinStochasticForcing& forcing) const {
      return std::make_unique<ZeitlinStochasticForcingFlow>(n(), forcing,
                                                            hamiltonian.laplacian().kappaSquared());
    }
    std::unique_ptr<ExactFlow<SUN>> fixed(const Eigen::MatrixXcd& forcing) const {
      return std::make_unique<ZeitlinFixedForcingFlow>(n(), forcing);
    }
  };
  return zeitlinExactFlowsBy(Make{hamiltonian}, d);
}

}  // namespace ddb
