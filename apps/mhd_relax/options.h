// mhd-relax's command line and its checks (docs/reference/command-lines-and-files.md, "mhd-relax";
// docs/reference/bad-inputs.md): the options as given, and the settings a run takes from them,
// every check made before anything is written.
#pragma once

#include <ddb/integrators/drivers/steady_state_search.h>

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "common/logging.h"
#include "common/relax_flags.h"

namespace ddb::mhd {

constexpr const char* kApp = "mhd-relax";
// The app's largest N: a DDB step costs about 60 complex N×N products, and every history row the
// O(N³) invariants.
constexpr Eigen::Index kMaxN = 1024;
constexpr long kMaxSteps = 1000000000L;
// Without --checkpoint-every, a checkpoint after the first step that ends this long after the
// last one: a killed run loses at most about this much work (fluid-relax's rule).
constexpr double kCheckpointSeconds = 300.0;

/// The methods of the method table that run on SU(N) ⋉ su(N)* (methodApplies), with the table's
/// descriptions.
std::vector<std::pair<std::string, std::string>> mhdMethods();

/// The options as given (numbers as text where messages quote them).
struct Options {
  long n = 32, steps = 0, every = 10, theta_lmax = 4;
  std::uint64_t seed = 1, theta_seed = 2;
  std::string alpha = "0.03", h = "0.01", t_end, method = "ddb-cay";
  std::string init = "random", init_file;  // W₀, as fluid-relax's
  /// Θ₀: --theta-file's CSV, or the low modes l ≤ --theta-lmax (lowModeVorticity) scaled to
  /// ‖Θ₀‖_F = --theta-scale · ‖W₀‖_F.
  std::string theta_file, theta_scale = "0.1";
  std::string out = "results-mhd";
  app::RelaxFlags relax;      // --until-steady, --adaptive, --adaptive-tol
  long checkpoint_every = 0;  // steps; 0: every kCheckpointSeconds of wall time
  std::string resume;         // the run folder to resume, or empty
  bool overwrite = false, plot = false;
  app::LogFlags log;
};

/// What a run takes from the options.
struct Settings {
  Eigen::MatrixXcd W0, Theta0;  // vorticity and magnetic potential
  double alpha = 0.0, h = 0.0;
  /// When the run stops: --until-steady, the cap (--steps, or --t-end's time with --adaptive,
  /// else its step count) and the step control.
  RelaxOptions relax;
  std::string init, theta_init;  // W₀'s (random, l1, zonal, file) and Θ₀'s (low-modes, file)
  std::filesystem::path out;
};

/// Adds every option, --version and the --help footer.
void addOptions(CLI::App& cli, Options& o);

/// Every check of the input in the order the messages name them: the method, α, h, the
/// relaxation flags, --steps or --t-end, --every, --checkpoint-every, W₀, Θ₀ and a first step
/// that does not overflow.
Settings settings(const CLI::App& cli, const Options& o);

/// The cap of --steps or --t-end (at most one; --steps 1000 if neither) into s.relax, for the
/// step s.h and s.relax.control.adaptive; a resumed run's new cap, which keeps the checkpoint's
/// if neither is given (`keep_if_none`).
void readStepCap(const CLI::App& cli, const Options& o, Settings& s, bool keep_if_none);

/// For --resume: refuses every flag but --steps, --t-end, --checkpoint-every, --plot, the
/// logging flags and an --out that is the --resume folder (the checkpoint's run is continued as
/// it was defined, in its folder), and a --checkpoint-every below 1.
void rejectFlagsBesideResume(const CLI::App& cli, const Options& o);

/// The checkpoint's options with this command line's --steps, --t-end, --checkpoint-every,
/// --plot, --resume and logging flags.
Options resumedOptions(const Options& given, const Options& recorded);

}  // namespace ddb::mhd
