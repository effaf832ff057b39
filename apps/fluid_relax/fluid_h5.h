// fluid.hdf5 (docs/reference/command-lines-and-files.md, "fluid.hdf5"): fluid-relax's frames in the
// layout of quflow's HDF5 files (quflow.io.save: `state` of qtype "shr", `time`, `qtime`), so that
// quflow.load opens it, plus the matrix W and history.csv's numbers per frame. Every
// per-frame dataset is chunked and extendable; a frame is one row of each.
#pragma once

#include <Eigen/Core>
#include <complex>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "common/hdf5.h"

namespace ddb::fluid {

/// The root attributes, written once by create().
struct FluidH5Attributes {
  long n = 0;
  double alpha = 0.0, h = 0.0;
  /// ħ = 2/√(N² − 1) of the run (docs/reference/conventions.md §2): qtime = t/ħ.
  double hbar = 0.0;
  std::string method, init;
  std::optional<std::uint64_t> seed;  // the generated inits
  std::string init_file;              // init "file"
  std::string version;
  std::string created;  // ISO 8601 UTC, e.g. 2026-11-24T15:40:00Z
};

/// A frame's field diagnostics (systems/zeitlin_spectra.h, systems/spherical_harmonic_grid.h), of
/// the relative vorticity W.
struct FluidH5Fields {
  double gamma = 0.0;
  const Eigen::VectorXd& energy_spectrum;     // E_l, l = 0..N − 1
  const Eigen::VectorXd& enstrophy_spectrum;  // Z_l
  /// ‖W_s‖²_F/(2N) and ‖W_r‖²_F/(2N) of the scale decomposition W = W_s + W_r (they sum to
  /// the enstrophy).
  double enstrophy_steady = 0.0, enstrophy_remainder = 0.0;
  const Eigen::MatrixXd& grid;  // ω on the N × (2N − 1) grid, quflow's "fun"
};

/// One frame: a row of history.csv and its state.
struct FluidH5Frame {
  long step = 0;
  double t = 0.0;
  const Eigen::MatrixXcd& W;
  /// ω_lm of W at l² + l + m (SphericalHarmonicBasis::coefficients), quflow's shr.
  const Eigen::VectorXd& omega;
  double energy = 0.0, enstrophy = 0.0, commutator_norm = 0.0, spectrum_drift = 0.0;
  /// The field diagnostics, for a file that has them (FluidH5::fields()).
  const FluidH5Fields* fields = nullptr;
};

class FluidH5 {
 public:
  /// Creates `path` (replacing a file of that name) with no frames. Throws IoError
  /// naming `path`.
  static FluidH5 create(const std::filesystem::path& path, const FluidH5Attributes& attributes);

  /// Opens an existing fluid.hdf5 for appending and shrinks every per-frame dataset to its
  /// first `frames` rows (a --resume from a checkpoint of `frames` frames). Throws IoError
  /// naming `path` if it cannot be opened, is not such a file (not HDF5, a dataset or the
  /// attribute N or hbar missing, rows of another shape than N) or has fewer than `frames`
  /// frames. Datasets of unequal lengths (a run killed within a frame) are cut alike. `fields`:
  /// whether the file has the field diagnostics' datasets (those of a run begun before 0.3.0
  /// have not, and go on without).
  static FluidH5 reopen(const std::filesystem::path& path, long frames, bool fields);

  /// Checks, reading only, that `path` is a fluid.hdf5 of the run `expected` describes (N,
  /// alpha, h, method, init and its seed or file; not version or created) with at least
  /// `frames` frames, with the field diagnostics' datasets if `fields`: what a --resume checks
  /// before it changes anything. Throws IoError naming `path` and what differs.
  static void checkResumable(const std::filesystem::path& path, const FluidH5Attributes& expected,
                             long frames, bool fields);

  /// Appends one frame (W must be N×N, omega of size N²). Throws IoError.
  void append(const FluidH5Frame& frame);

  /// Writes everything appended to the disk (H5Fflush): before a checkpoint.
  void flush();

  long frames() const { return frames_; }
  /// Whether the frames hold the field diagnostics (FluidH5Fields).
  bool fields() const { return fields_; }
  long n() const { return n_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  FluidH5(std::filesystem::path path, long n, double hbar);
  /// Writes the datasets and attributes of a new file.
  void writeLayout(const FluidH5Attributes& attributes);
  /// Opens every dataset (with fields_, the field diagnostics' too), checks the shapes and sets
  /// frames_ to their shortest length.
  void openDatasets();

  std::filesystem::path path_;
  long n_ = 0;
  double hbar_ = 0.0;
  long frames_ = 0;
  app::hdf5::Handle file_, complex_;
  app::hdf5::Handle state_, mat_, time_, qtime_, step_, energy_, enstrophy_, commutator_, drift_;
  bool fields_ = true;
  app::hdf5::Handle gamma_, energy_spectrum_, enstrophy_spectrum_, enstrophy_steady_,
      enstrophy_remainder_, grid_;
  /// W in row-major order (HDF5's), reused by every append.
  Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> grid_row_major_;
};

}  // namespace ddb::fluid
