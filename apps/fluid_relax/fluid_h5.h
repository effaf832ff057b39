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

/// One frame: a row of history.csv and its state.
struct FluidH5Frame {
  long step = 0;
  double t = 0.0;
  const Eigen::MatrixXcd& W;
  /// ω_lm of W at l² + l + m (SphericalHarmonicBasis::coefficients), quflow's shr.
  const Eigen::VectorXd& omega;
  double energy = 0.0, enstrophy = 0.0, commutator_norm = 0.0, spectrum_drift = 0.0;
};

class FluidH5 {
 public:
  /// The current time as ISO 8601 UTC ("2026-11-24T15:40:00Z"), for `created`.
  static std::string utcNow();

  /// Creates `path` (replacing a file of that name) with no frames. Throws IoError
  /// naming `path`.
  static FluidH5 create(const std::filesystem::path& path, const FluidH5Attributes& attributes);

  /// Opens an existing fluid.hdf5 for appending and shrinks every per-frame dataset to its
  /// first `frames` rows (a --resume from a checkpoint of `frames` frames). Throws IoError
  /// naming `path` if it cannot be opened, is not such a file (not HDF5, a dataset or the
  /// attribute N or hbar missing, rows of another shape than N) or has fewer than `frames`
  /// frames. Datasets of unequal lengths (a run killed within a frame) are cut alike.
  static FluidH5 reopen(const std::filesystem::path& path, long frames);

  /// Checks, reading only, that `path` is a fluid.hdf5 of the run `expected` describes (N,
  /// alpha, h, method, init and its seed or file; not version or created) with at least
  /// `frames` frames: what a --resume checks before it changes anything. Throws IoError
  /// naming `path` and what differs.
  static void checkResumable(const std::filesystem::path& path, const FluidH5Attributes& expected,
                             long frames);

  /// Appends one frame (W must be N×N, omega of size N²). Throws IoError.
  void append(const FluidH5Frame& frame);

  /// Writes everything appended to the disk (H5Fflush): before a checkpoint.
  void flush();

  long frames() const { return frames_; }
  long n() const { return n_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  FluidH5(std::filesystem::path path, long n, double hbar);
  /// Writes the datasets and attributes of a new file.
  void writeLayout(const FluidH5Attributes& attributes);
  /// Opens every dataset, checks the shapes and sets frames_ to their shortest length.
  void openDatasets();

  std::filesystem::path path_;
  long n_ = 0;
  double hbar_ = 0.0;
  long frames_ = 0;
  app::hdf5::Handle file_, complex_;
  app::hdf5::Handle state_, mat_, time_, qtime_, step_, energy_, enstrophy_, commutator_, drift_;
  /// W in row-major order (HDF5's), reused by every append.
  Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major_;
};

}  // namespace ddb::fluid
