#include "fluid_relax/options.h"

#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_step_size.h>

#include "common/cli.h"
#include "common/format.h"
#include "common/initial_vorticity.h"

namespace ddb::fluid {

std::vector<std::pair<std::string, std::string>> fluidMethods() {
  std::vector<std::pair<std::string, std::string>> methods;
  for (const MethodInfo& m : kMethods) {
    // Those that run on every backend: the CPU's, one GPU's (--device cuda) and the MPI ranks'
    // (fluid-relax-mpi) alike.
    if ((m.groups & kBackendMatrixGroups) != 0) {
      methods.emplace_back(m.name, m.description);
    }
  }
  return methods;
}

void addOptions(CLI::App& cli, Options& o, Eigen::Index max_n) {
  cli.add_option("--n", o.n, "resolution N, 2 <= N <= " + std::to_string(max_n))
      ->capture_default_str()
      ->check(app::fitsIn<long>());
  cli.add_option("--alpha", o.alpha,
                 "double-bracket coefficient (> 0 relaxes to lower energy, < 0 raises it)")
      ->capture_default_str();
  cli.add_option("--rotation", o.rotation,
                 "the sphere's angular velocity Omega (planetary vorticity 2 Omega cos(theta)): "
                 "the states are absolute vorticities W + F, history.csv's and fluid.hdf5's the "
                 "relative W (docs/guide/matrix-groups-and-the-fluid.md)")
      ->capture_default_str();
  cli.add_option("--deformation-radius", o.deformation_radius,
                 "quasi-geostrophic flow with deformation radius L_d > 0 (in sphere radii): the "
                 "stream matrix (Laplacian - 1/L_d^2)^-1 (W); default none (Euler)");
  cli.add_option(
         "--viscosity", o.viscosity,
         "viscosity nu >= 0: dW/dt gains nu (-1)^(p+1) Laplacian^p W, solved exactly "
         "and Strang-split around --method (not yet with --device cuda; leaves the orbit by "
         "design)")
      ->capture_default_str();
  cli.add_option("--hyperviscosity-order", o.hyperviscosity_order,
                 "the order p of --viscosity, 1 <= p <= " +
                     std::to_string(kMaxHyperviscosityOrder) + " (1: Laplacian viscosity)")
      ->capture_default_str()
      ->check(app::fitsIn<long>());
  cli.add_option("--drag", o.drag, "linear drag gamma >= 0: dW/dt gains -gamma W, as --viscosity")
      ->capture_default_str();
  cli.add_option("--viscous-scheme", o.viscous_scheme,
                 "how --viscosity and --drag step: exact (exp(-hA) in the spherical harmonics, "
                 "N^3/6 numbers kept) or implicit ((I + hA + (hA)^2/2)^-1, second order, a banded "
                 "solve per diagonal: much cheaper at large N)")
      ->capture_default_str();
  cli.add_option("--forcing-band", o.forcing_band,
                 "L:D, stochastic forcing of the degrees L-D..L+D (within 1..N-1; L alone: D = 0), "
                 "white in time, Strang-split as --viscosity (needs --forcing-rate)");
  cli.add_option("--forcing-rate", o.forcing_rate,
                 "the forcing's mean energy injection rate epsilon >= 0 (energy per unit time)")
      ->capture_default_str();
  app::addSeedOption(cli, o.forcing_seed,
                     "seed of the forcing's random stream (a checkpoint keeps its position)",
                     "--forcing-seed");
  cli.add_option("--forcing-file", o.forcing_file,
                 "a fixed forcing Phi, dW/dt gains Phi: a CSV as --init-file's (N rows x 2N "
                 "columns, traceless skew-Hermitian), Strang-split as --viscosity");
  cli.add_option("--h", o.h,
                 "step size (default min(" + app::number(kZeitlinContractionRate) +
                     " hbar/||P0||_2, " + app::number(kZeitlinStiffness) +
                     " hbar/(|alpha| ||W0||_2^2)" + ", and " +
                     app::number(kZeitlinContractionRate) +
                     "/|Omega| with --rotation), P0 the initial stream matrix; recorded in "
                     "summary.json)");
  cli.add_option("--steps", o.steps, "number of steps (exactly one of --steps and --t-end)")
      ->check(app::fitsIn<long>());
  cli.add_option("--t-end", o.t_end,
                 "final time: round(T/h) steps of the given --h, or with the default h the "
                 "smallest step count whose equal steps are no longer than it");
  app::addRelaxFlags(cli, o.relax,
                     "stop when r = ||[P,W]||_F/(||P||_F ||W||_F) <= TOL, 0 < TOL < 1 (--steps or "
                     "--t-end is then the cap; summary.json says which stopped the run)",
                     "choose h by the energy (docs/guide/steady-states.md): a DDB-family method "
                     "with alpha != 0; --h is the first step, --steps caps accepted steps");
  cli.add_flag("--newton", o.newton,
               "instead of time steps, Newton's method on the orbit for a steady state "
               "(docs/guide/steady-states.md): needs --until-steady, --steps caps its iterations; "
               "no --method, --h, --t-end or --adaptive");
  app::addSeedOption(cli, o.seed, "seed of the initial vorticity");
  cli.add_option("--init", o.init, "initial vorticity (listed below)")->capture_default_str();
  cli.add_option("--init-file", o.init_file,
                 "read W0 from a CSV of N rows x 2N columns (row j: Re W[j,:] then Im W[j,:]); "
                 "N is taken from the file");
  cli.add_option("--method", o.method, "integrator (listed below)")->capture_default_str();
  cli.add_option("--every", o.every, "write every K-th state and the last one to history.csv")
      ->capture_default_str()
      ->check(app::fitsIn<long>());
  app::addRunFolderFlags(cli, o.out, o.overwrite);
  cli.add_option("--checkpoint-every", o.checkpoint_every,
                 "write OUT/checkpoint.ddb every K accepted steps (default: every " +
                     app::number(kCheckpointSeconds) +
                     " s of wall time), and always at the end of the run")
      ->check(app::fitsIn<long>());
  cli.add_option("--resume", o.resume,
                 "continue the run in DIR from its checkpoint, to the bit as if never stopped, "
                 "with its recorded settings; --steps or --t-end may set a new cap");
  cli.add_flag("--plot", o.plot, "render PNG figures (python3 with matplotlib and scipy)");
  cli.add_flag("--h5", o.h5,
               "write every history.csv row's state to fluid.hdf5 (quflow's layout, "
               "docs/reference/command-lines-and-files.md)");
  cli.add_flag("--animate", o.animate,
               "render fluid.mp4 from fluid.hdf5 after the run (implies --h5; python3 with "
               "matplotlib, scipy, h5py and ffmpeg)");
  app::addLogFlags(cli, o.log);
  app::addVersionFlag(cli, kApp);
  cli.footer(
      "\nInitial vorticities (--init; all scaled to ||W||_F = sqrt(N), seeded by --seed):\n" +
      app::describeChoices(app::initDescriptions()) + "\nMethods (--method):\n" +
      app::describeChoices(fluidMethods()) +
      "\nFiles in --out: history.csv, W_final.csv, omega_initial.csv, omega_final.csv, "
      "summary.json, checkpoint.ddb,\nfluid.hdf5 with --h5, fluid.mp4 with --animate "
      "(docs/reference/command-lines-and-files.md).\nExit status: 0 ok, 1 a step failed or a "
      "file could not be written, 2 bad input (nothing written), 130/143 stopped by SIGINT/SIGTERM "
      "(outputs "
      "and a checkpoint written; --resume continues).\n");
}

}  // namespace ddb::fluid
