// mhd-relax's fluid.hdf5 (docs/reference/command-lines-and-files.md, "mhd-relax"): both fields of
// every history row in quflow's layout, W at the root (`state` of qtype "shr", `time`, `qtime`,
// as fluid-relax writes it, so that quflow.load opens it) and Θ in the group `theta` (the same
// three datasets: quflow.load(file, datapath="/theta")), with history.csv's numbers per frame.
// It is written as `fluid.hdf5.partial` and renamed by commit(): a file named fluid.hdf5 is
// complete.
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
  /// Removes the partial file unless commit() succeeded: a run that ends by an exception (a file
  /// it could not write) leaves no half-written HDF5 file. A killed run cannot, and leaves it.
  ~MhdH5();
  MhdH5(const MhdH5&) = delete;
  MhdH5& operator=(const MhdH5&) = delete;

  /// Appends one frame: ω_lm of W and of Θ (N² each) and its numbers. Throws IoError.
  void append(const Eigen::VectorXd& omega_w, const Eigen::VectorXd& omega_theta,
              const MhdFrameNumbers& numbers);
  /// Closes the file and renames it onto its name (durably). Throws IoError.
  void commit();

  long frames() const { return frames_; }

 private:
  /// Closes every handle, the file's last.
  void close() noexcept;

  std::filesystem::path path_, partial_;
  long n_ = 0;
  double hbar_ = 0.0;
  long frames_ = 0;
  bool committed_ = false;
  app::hdf5::Handle file_;
  app::hdf5::Handle state_, time_, qtime_, theta_state_, theta_time_, theta_qtime_, step_, kinetic_,
      magnetic_, cross_, residual_, equilibrium_, drift_;
};

}  // namespace ddb::mhd
