// fluid-relax's CSV files (docs/file-formats.md, "fluid-relax"): history.csv as the run
// goes (continued by a resumed run), W_final.csv in the layout of --init-file, omega_initial.csv
// and omega_final.csv.
#pragma once

#include <ddb/systems/spherical_harmonic_basis.h>

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>

#include "common/atomic_file.h"
#include "common/csv_row.h"
#include "common/journal_file.h"
#include "fluid_relax/fluid_h5.h"
#include "fluid_relax/input.h"

namespace ddb::fluid {

/// history.csv: one row per written state, appended as the run goes (a JournalFile, which a
/// resumed run continues).
class HistoryCsv {
 public:
  /// Creates the file with its header.
  explicit HistoryCsv(const std::filesystem::path& path);
  /// Continues the file of a resumed run from the `length` bytes its checkpoint recorded.
  HistoryCsv(const std::filesystem::path& path, std::uint64_t length);
  void write(double t, double energy, double enstrophy, double commutator_norm,
             double spectrum_drift, double h, double residual);
  /// Makes the rows written durable; returns the file's length (for a checkpoint).
  std::uint64_t sync() { return file_.sync(); }
  /// Completes the file under its name (JournalFile::commit).
  void commit() { file_.commit(); }

 private:
  app::JournalFile file_;
  app::CsvRow row_;
};

/// The name of --h5's file in --out: quflow.load opens only names ending in "hdf5".
constexpr const char* kFluidH5 = "fluid.hdf5";

/// fluid.hdf5's root attributes for the run of `o`, `s` (ħ of the run's Hamiltonian).
FluidH5Attributes h5Attributes(const Options& o, const Settings& s, double hbar);

/// W in the layout of --init-file: row j is Re W[j, :] then Im W[j, :].
void writeMatrixCsv(const std::filesystem::path& path, const Eigen::MatrixXcd& W);

/// The real spherical-harmonic coefficients ω_lm of W (docs/conventions.md §2), one row
/// "l,m,omega" each, for the figures.
void writeOmegaCsv(const std::filesystem::path& path, const SphericalHarmonicBasis& basis,
                   const Eigen::MatrixXcd& W);

}  // namespace ddb::fluid
