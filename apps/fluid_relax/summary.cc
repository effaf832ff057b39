#include "fluid_relax/summary.h"

#include <cmath>

#include "common/cli.h"

namespace ddb::fluid {

app::Json runSummary(const Options& o, const Settings& s, const LiePoissonSystem<SUN>& system,
                     const RelaxResult<SUN>& result, const Tally& tally,
                     const std::string& method_name, bool counts_iterations, bool watch_energy,
                     double runtime_s, const std::string& device) {
  const Eigen::Index n = s.W0.rows();
  const ZeitlinDiagnostics diagnostics(
      dynamic_cast<const ZeitlinHamiltonian&>(system.hamiltonian()));
  const bool newton = s.relax.newton;
  const bool interrupted = result.stop == RelaxStop::kInterrupted;
  app::Json summary;
  summary["version"] = app::projectVersion();
  summary["status"] = !result.ok() ? "FAILED" : interrupted ? "interrupted" : "ok";
  summary["n"] = n;
  summary["alpha"] = s.alpha;
  summary["h"] = newton ? app::Json() : app::Json(s.h);
  summary["h_source"] = newton ? app::Json() : app::Json(s.default_h ? "default" : "--h");
  summary["steps"] = result.last.k;
  summary["steps_requested"] = s.steps;
  summary["t_end"] = result.last.t;
  summary["stop"] = relaxStopName(result.stop);
  summary["steady"] = result.steady();
  summary["until_steady"] = s.relax.tolerance > 0 ? app::Json(s.relax.tolerance) : app::Json();
  summary["residual_final"] = steadyStateResidual(system, result.final);
  summary["adaptive"] = s.relax.control.adaptive;
  summary["newton"] = newton;
  summary["adaptive_tol"] =
      s.relax.control.adaptive ? app::Json(s.relax.control.tolerance) : app::Json();
  summary["steps_rejected"] = result.steps_rejected;
  summary["h_final"] = result.last.h;
  summary["every"] = o.every;
  summary["method"] = method_name;
  summary["device"] = device;
  summary["init"] = s.init;
  summary["seed"] = s.init == "file" ? app::Json() : app::Json(o.seed);
  summary["init_file"] = s.init == "file" ? app::Json(o.init_file) : app::Json();
  // The physics, and the diagnostics of the states Q (absolute vorticities on a rotating sphere).
  summary["rotation"] = s.physics.rotation;
  summary["deformation_radius"] = std::isinf(s.physics.deformation_radius)
                                      ? app::Json()
                                      : app::Json(s.physics.deformation_radius);
  summary["viscosity"] = s.viscosity.viscosity;
  summary["hyperviscosity_order"] = s.viscosity.order;
  summary["drag"] = s.viscosity.drag;
  summary["viscous_scheme"] = o.viscous_scheme;
  const ZeitlinStochasticForcing& f = s.forcing;
  summary["forcing_band"] =
      f.forces()
          ? app::Json(std::to_string(f.band_centre) + ":" + std::to_string(f.band_half_width))
          : app::Json();
  summary["forcing_rate"] = f.rate;
  summary["forcing_seed"] = f.forces() ? app::Json(f.seed) : app::Json();
  summary["forcing_file"] = o.forcing_file.empty() ? app::Json() : app::Json(o.forcing_file);
  const Eigen::MatrixXcd Q0 = s.initialState();
  summary["energy_initial"] = diagnostics.energy(Q0);
  summary["energy_final"] = diagnostics.energy(result.final);
  summary["enstrophy_initial"] = diagnostics.enstrophy(Q0);
  summary["enstrophy"] = diagnostics.enstrophy(result.final);
  summary["spectrum_drift_max"] = tally.drift_max;
  summary["commutator_initial"] = diagnostics.commutatorNorm(Q0);
  summary["commutator_final"] = diagnostics.commutatorNorm(result.final);
  summary["runtime_s"] = runtime_s;
  if (counts_iterations) {
    summary["iterations_mean"] =
        result.last.k > 0 ? static_cast<double>(tally.iterations_total) / result.last.k : 0.0;
    summary["iterations_max"] = tally.iterations_max;
  } else {  // no equation solved: not applicable
    summary["iterations_mean"] = app::Json();
    summary["iterations_max"] = app::Json();
  }
  if (watch_energy) summary["energy_rises"] = tally.rises.count();
  if (!result.ok()) {
    summary["failed_step"] = result.failed_step;
    summary["failure"] = result.failure;
  }
  return summary;
}

}  // namespace ddb::fluid
