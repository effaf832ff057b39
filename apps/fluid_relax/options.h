// fluid-relax's command line (docs/reference/command-lines-and-files.md, "fluid-relax"): the
// options and --help with the initial vorticities and methods.
#pragma once

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "common/logging.h"
#include "common/relax_flags.h"

namespace ddb::fluid {

constexpr const char* kApp = "fluid-relax";
// The app's largest N, below SUN::kMaxN: a DDB step costs about 20 complex N×N products
// (docs/reference/conventions.md §4), some seconds each step at N = 1024 on two cores, and every
// state's spectrum is computed for spectrum_drift.
constexpr Eigen::Index kMaxN = 1024;
constexpr long kMaxSteps = 1000000000L;
// --hyperviscosity-order's largest p: the field's runs use p <= 8 (GLIFS, quflow), and
// (l(l + 1))^p stays finite for every l <= SUN::kMaxN.
constexpr long kMaxHyperviscosityOrder = 16;
/// The largest |W0| + t |Phi| a run with --forcing-file may reach (Frobenius norms): its energy
/// and enstrophy, below |W|², stay finite.
constexpr double kMaxForcedNorm = 1e150;
// Without --checkpoint-every, a checkpoint after the first step that ends this long after
// the last one: a killed run loses at most about this much work.
constexpr double kCheckpointSeconds = 300.0;

/// The methods for the fluid: the method table's entries for any backend's matrices (every
/// matrix-group method but the reference), which fluid-relax runs on the CPU or one GPU and
/// fluid-relax-mpi on MPI ranks, with the table's descriptions.
std::vector<std::pair<std::string, std::string>> fluidMethods();

/// The options as given (numbers as text where messages quote them).
struct Options {
  long n = 32, steps = 0, every = 1;
  std::uint64_t seed = 1;
  std::string alpha = "0.5", h, t_end, init = "random", init_file, method = "ddb-cay";
  /// The sphere's rotation Ω and quasi-geostrophy's deformation radius (ZeitlinPhysics; empty
  /// radius: none, Euler).
  std::string rotation = "0", deformation_radius;
  /// Viscosity ν, its order p (1: Laplacian, > 1 hyperviscosity) and linear drag γ
  /// (ZeitlinViscosity), by Strang splitting around --method.
  std::string viscosity = "0", drag = "0";
  long hyperviscosity_order = 1;
  /// How the viscous flow steps: "exact" or "implicit" (ZeitlinViscousScheme).
  std::string viscous_scheme = "exact";
  /// Band-limited white-in-time forcing (ZeitlinStochasticForcing), Strang-split as the damping:
  /// the degrees L - D .. L + D of --forcing-band L:D (empty: none), the mean energy injection rate
  /// and the random stream's seed.
  std::string forcing_band, forcing_rate = "0";
  std::uint64_t forcing_seed = 1;
  /// A fixed forcing Φ (ZeitlinFixedForcingFlow), as --init-file's CSV (empty: none).
  std::string forcing_file;
  std::string out = "results-fluid";
  app::RelaxFlags relax;      // --until-steady, --adaptive, --adaptive-tol
  bool newton = false;        // --newton: OrbitNewton's search instead of steps
  long checkpoint_every = 0;  // steps; 0: every kCheckpointSeconds of wall time
  std::string resume;         // the run folder to resume, or empty
  bool overwrite = false;     // a new run may replace another run's files in --out
  bool plot = false;
  bool h5 = false, animate = false;  // fluid.hdf5; its animation (implies h5)
  /// fluid-relax's --device (fluid_relax/device.h): cpu or cuda; not in a checkpoint, so that
  /// a run resumes on either.
  std::string device = "cpu";
  app::LogFlags log;
};

/// Adds every option of Options, --version and the --help footer.
void addOptions(CLI::App& cli, Options& o, Eigen::Index max_n);

}  // namespace ddb::fluid
