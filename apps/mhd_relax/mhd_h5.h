// mhd-relax's fluid.hdf5 (docs/reference/command-lines-and-files.md, "mhd-relax"): both fields of
// every history row in quflow's layout, W at the root (`state` of qtype "shr", `time`, `qtime`,
// as fluid-relax writes it, so that quflow.load opens it) and Θ in the group `theta` (the same
// three datasets: quflow.load(file, datapath="/theta")), with history.csv's numbers per frame.
// It is written as `fluid.hdf5.partial` and renamed by commit(): a file named fluid.hdf5 is
// complete. As history.csv's journal, no failure removes the partial file: a checkpoint may refer
// to it (mhd_relax/checkpoint.h), flushed before each.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>

#include "common/hdf5.h"

namespace ddb::mhd {

/// The root attributes, written once by create().
struct MhdH5Attributes {
  long n = 0;
  double alpha = 0.0, h = 0.0;
  double hbar = 0.0;  // ħ = 2/√(N² − 1): qtime = t/ħ
  std::string method, init, theta_init, version, created;
};

/// One frame's numbers (history.csv's row).
struct MhdFrameNumbers {
  long step = 0;
  double t = 0.0, kinetic_energy = 0.0, magnetic_energy = 0.0, cross_helicity = 0.0, residual = 0.0,
         equilibrium_residual = 0.0, invariant_drift = 0.0;
};

class MhdH5 {
 public:
  /// Creates `<path>.partial` (replacing a file of that name) with no frames. Throws IoError
  /// naming it; a file it could not complete is removed.
  MhdH5(std::filesystem::path path, const MhdH5Attributes& attributes);
  MhdH5(const MhdH5&) = delete;
  MhdH5& operator=(const MhdH5&) = delete;

  /// Continues the file of a resumed run, `<path>.partial` (or `path`, which a finished or
  /// interrupted run completed, renamed back to it), cut to its first `frames` frames. Throws
  /// IoError naming it if it cannot be opened, is not such a file (a dataset missing, rows of
  /// another N) or has fewer frames.
  MhdH5(std::filesystem::path path, long n, double hbar, long frames);

  /// Checks, reading only, that `path` (or its .partial) is such a file with at least `frames`
  /// frames of N = n: what a --resume checks before it changes anything. Throws IoError.
  static void checkResumable(const std::filesystem::path& path, long n, long frames);

  /// Appends one frame: ω_lm of W and of Θ (N² each) and its numbers. Throws IoError.
  void append(const Eigen::VectorXd& omega_w, const Eigen::VectorXd& omega_theta,
              const MhdFrameNumbers& numbers);
  /// Writes everything appended to the disk (H5Fflush): before a checkpoint.
  void flush();
  /// Closes the file and renames it onto its name (durably). Throws IoError.
  void commit();

  long frames() const { return frames_; }

 private:
  /// Opens every dataset of file_ (a file of N = n_) and sets frames_ to their shortest length.
  void openDatasets();
  /// Closes every handle, the file's last.
  void close() noexcept;

  std::filesystem::path path_, partial_;
  long n_ = 0;
  double hbar_ = 0.0;
  long frames_ = 0;
  app::hdf5::Handle file_;
  app::hdf5::Handle state_, time_, qtime_, theta_state_, theta_time_, theta_qtime_, step_, kinetic_,
      magnetic_, cross_, residual_, equilibrium_, drift_;
};

}  // namespace ddb::mhd
