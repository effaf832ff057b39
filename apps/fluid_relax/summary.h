// fluid-relax's summary.json (docs/reference/command-lines-and-files.md, "fluid-relax"): the fields
// of a run, whichever app ran it (fluid-relax, or fluid-relax-mpi, which adds its own).
#pragma once

#include <ddb/groups/sun.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/systems/zeitlin_fluid.h>

#include <string>
#include <utility>

#include "common/json.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/input.h"
#include "fluid_relax/options.h"

namespace ddb::fluid {

/// summary.json of the run of `o`, `s` on the fluid `system` that ended in `result` (its
/// final state whole), with the accumulated `tally`, its method's name and its wall time.
/// `counts_iterations`: whether the method solves equations (OneStepMethod::solvesEquations;
/// otherwise the iterations are null, not applicable); `watch_energy`: whether energy rises
/// were counted (app::EnergyRises::applies); `device`: where the states lived ("cpu", or
/// "cuda: " and the GPU's name).
/// A run's result on another backend with its final state `final` in this process's memory
/// (fluid-relax-mpi's gathered on rank 0, fluid-relax's copied from the GPU): what runSummary
/// and the final files read.
template <class G>
RelaxResult<SUN> resultWithFinal(const RelaxResult<G>& result, Eigen::MatrixXcd final) {
  RelaxResult<SUN> host;
  host.final = std::move(final);
  host.last = result.last;
  host.stop = result.stop;
  host.steps_rejected = result.steps_rejected;
  host.runtime_s = result.runtime_s;
  host.failure = result.failure;
  host.failed_step = result.failed_step;
  return host;
}

app::Json runSummary(const Options& o, const Settings& s, const LiePoissonSystem<SUN>& system,
                     const RelaxResult<SUN>& result, const Tally& tally,
                     const std::string& method_name, bool counts_iterations, bool watch_energy,
                     double runtime_s, const std::string& device);

}  // namespace ddb::fluid
