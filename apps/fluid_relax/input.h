// fluid-relax's input, validated: the numbers of the command line, the initial
// vorticity (generated, or read from --init-file) and the step, or a UsageError naming
// the flag (docs/reference/bad-inputs.md).
#pragma once

#include <ddb/integrators/drivers/relax.h>
#include <ddb/systems/zeitlin_forcing.h>
#include <ddb/systems/zeitlin_hamiltonian.h>
#include <ddb/systems/zeitlin_viscosity.h>

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <utility>

#include "fluid_relax/options.h"

namespace ddb::fluid {

using Matrix = Eigen::MatrixXcd;

/// Everything the run needs, validated.
struct Settings {
  Matrix W0;  // the relative vorticity
  double alpha = 0.0, h = 0.0;
  ZeitlinPhysics physics;            // --rotation, --deformation-radius
  ZeitlinViscosity viscosity;        // --viscosity, --hyperviscosity-order, --drag
  ZeitlinStochasticForcing forcing;  // --forcing-band, --forcing-rate, --forcing-seed
  Matrix fixed_forcing;              // --forcing-file's Φ (empty: none)
  bool default_h = false;
  long steps = 0;
  /// When relax() stops: --until-steady, the cap (--steps, or --t-end's time with
  /// --adaptive, else its step count) and the step control.
  RelaxOptions relax;
  std::string init;  // random, l1, zonal or file
  std::filesystem::path out;

  /// Whether the run is forced (stochastically or by a fixed Φ): its energy rises by design.
  bool forced() const { return forcing.forces() || fixed_forcing.size() > 0; }

  /// The run's first state: the absolute vorticity W0 + F (W0 itself without rotation, and on
  /// fluid-relax-mpi's ranks but rank 0, which hold no W0).
  Matrix initialState() const {
    if (physics.rotation == 0.0 || W0.size() == 0) return W0;
    return W0 + zeitlinPlanetaryVorticity(W0.rows(), physics.rotation);
  }
};

/// Every check of the input (docs/reference/bad-inputs.md) in the order the messages name them:
/// the method, α, the physics (--rotation to --drag), --steps or --t-end, --until-steady,
/// --adaptive and --adaptive-tol, W0
/// (--init-file read and checked, or generated), h (given or the default) and a first step that
/// does not overflow.
Settings settings(const CLI::App& cli, const Options& o, Eigen::Index max_n);

/// The flag and text that name the run's exact flows (the damping's, then the forcing's, then the
/// fixed forcing's: the first given), for a message that refuses them; empty if the run has none.
std::pair<std::string, std::string> exactFlowFlag(const Options& o, const Settings& s);

struct Checkpoint;

/// For --resume: checks the command line against the checkpoint's (a flag that would change
/// the run is a UsageError naming it; --steps or --t-end may set a new cap) and turns the
/// checkpoint's options and settings into the resumed run's: the recorded ones with the
/// new cap and this command line's --checkpoint-every, --plot and logging flags. Whether
/// the cap lies beyond the checkpoint's state is checked once that state is loaded.
void resumeSettings(const CLI::App& cli, const Options& given, Checkpoint& c);

}  // namespace ddb::fluid
