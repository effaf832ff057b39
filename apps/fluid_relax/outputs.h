// fluid-relax's CSV files (docs/reference/command-lines-and-files.md, "fluid-relax"): history.csv
// as the run goes (continued by a resumed run) with fluid.hdf5's frames beside it, W_final.csv in
// the layout of --init-file, omega_initial.csv and omega_final.csv.
#pragma once

#include <ddb/integrators/drivers/steady_state_probe.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/spherical_harmonic_grid.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_spectra.h>

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <optional>

#include "common/atomic_file.h"
#include "common/csv_row.h"
#include "common/journal_file.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/fluid_h5.h"
#include "fluid_relax/input.h"

namespace ddb::fluid {

/// history.csv: one row per written state, appended as the run goes (a JournalFile, which a
/// resumed run continues).
class HistoryCsv {
 public:
  /// Creates the file with its header.
  explicit HistoryCsv(const std::filesystem::path& path);
  /// Continues the file of a resumed run from the `length` bytes its checkpoint recorded,
  /// whose hash is `digest` (checked by checkResumeFolder), with the gamma column if it has it
  /// (the files of a run begun before 0.3.0 have not).
  HistoryCsv(const std::filesystem::path& path, std::uint64_t length, std::uint64_t digest,
             bool gamma_column);
  void write(double t, double energy, double enstrophy, double commutator_norm,
             double spectrum_drift, double h, double residual, double gamma);
  /// Makes the rows written durable; returns the file's length (for a checkpoint).
  std::uint64_t sync() { return file_.sync(); }
  /// The hash of the file's bytes so far (JournalFile::digest).
  std::uint64_t digest() const { return file_.digest(); }
  /// Completes the file under its name (JournalFile::commit).
  void commit() { file_.commit(); }

 private:
  app::JournalFile file_;
  app::CsvRow row_;
  bool gamma_column_;
};

/// The name of the history's file in --out (a JournalFile: `.partial` while a run writes it).
constexpr const char* kHistoryCsv = "history.csv";

/// The name of --h5's file in --out: quflow.load opens only names ending in "hdf5".
constexpr const char* kFluidH5 = "fluid.hdf5";

/// fluid.hdf5's root attributes for the run of `o`, `s` (ħ of the run's Hamiltonian).
FluidH5Attributes h5Attributes(const Options& o, const Settings& s, double hbar);

/// The files of the history rows: history.csv's row of a state and, with --h5 or --animate,
/// its frame in fluid.hdf5, from one evaluation of the state's numbers; fluid-relax's, and
/// fluid-relax-mpi's on rank 0 from the gathered states.
class HistoryFiles {
 public:
  /// The lengths a checkpoint records.
  using Lengths = FileLengths;

  /// New files in s.out, or (resume) a resumed run's, continued from the lengths its
  /// checkpoint recorded (the folder checked by checkResumeFolder). `system` is the run's fluid
  /// (makeZeitlinFluid). Throws IoError.
  HistoryFiles(const Options& o, const Settings& s, const LiePoissonSystem<SUN>& system,
               const Checkpoint* resume);
  /// The row of state k (the absolute vorticity Q) at time t reached by a step h (0 for k = 0),
  /// of spectrum drift `drift`.
  void write(long k, double t, double h, const Eigen::MatrixXcd& Q, double drift);
  /// Makes the rows written durable (before a checkpoint) and returns their lengths.
  Lengths sync();
  /// Completes history.csv under its name and writes fluid.hdf5 to the disk.
  void commit();
  const SphericalHarmonicBasis& basis() const { return basis_; }

 private:
  const ZeitlinHamiltonian& hamiltonian_;
  ZeitlinDiagnostics diagnostics_;
  Eigen::MatrixXcd relative_;    // a frame's W = Q − F on a rotating sphere
  SteadyStateProbe<SUN> probe_;  // r of each row, whether or not the run evaluates it
  SphericalHarmonicBasis basis_;
  ZeitlinGammaFromMatrix gamma_;
  bool field_diagnostics_;   // FileLengths::field_diagnostics
  Eigen::VectorXd omega_;    // a row's coefficients
  Eigen::MatrixXcd stream_;  // a frame's ψ
  std::optional<SphericalHarmonicGrid> grid_;
  std::optional<HistoryCsv> csv_;
  std::optional<FluidH5> h5_;
};

/// The figures a finished run asks for, once it ended with exit status `status`: with
/// --animate fluid.hdf5's animation (fluid.mp4) by `animate_script`, with --plot the figures
/// by `plot_script` (the app's own paths); none after a failure. Returns the app's exit status:
/// kExitFailed if a figure failed, which summary.json then records (app::recordFiguresFailure).
int makeFigures(const Options& o, const std::filesystem::path& out, int status,
                const char* plot_script, const char* animate_script);

/// The real spherical-harmonic coefficients ω_lm of W (docs/reference/conventions.md §2), one row
/// "l,m,omega" each, for the figures.
void writeOmegaCsv(const std::filesystem::path& path, const SphericalHarmonicBasis& basis,
                   const Eigen::MatrixXcd& W);

}  // namespace ddb::fluid
