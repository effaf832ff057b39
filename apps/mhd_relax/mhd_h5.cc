#include "mhd_relax/mhd_h5.h"

#include <cstdio>
#include <system_error>
#include <utility>

#include "common/atomic_file.h"
#include "common/exit_status.h"

namespace ddb::mhd {

namespace {

using app::hdf5::Handle;

/// Creates in `on` the datasets quflow reads, `state` (ω_lm, qtype "shr"), `time` and `qtime`.
void createQuflowDatasets(hid_t on, long n, const std::filesystem::path& file, Handle& state,
                          Handle& time, Handle& qtime) {
  const app::hdf5::RowShape number, omega{1, {static_cast<hsize_t>(n * n), 0}};
  state = app::hdf5::createDataset(on, "state", H5T_IEEE_F64LE, omega, file);
  app::hdf5::writeAttribute(state.get(), "qtype", "shr", file);
  time = app::hdf5::createDataset(on, "time", H5T_IEEE_F64LE, number, file);
  qtime = app::hdf5::createDataset(on, "qtime", H5T_IEEE_F64LE, number, file);
  const std::int64_t n64 = n;
  app::hdf5::writeAttribute(on, "N", H5T_NATIVE_INT64, &n64, file);
}

}  // namespace

MhdH5::MhdH5(std::filesystem::path path, const MhdH5Attributes& attributes)
    : path_(std::move(path)),
      partial_(path_.string() + ".partial"),
      n_(attributes.n),
      hbar_(attributes.hbar) {
  app::hdf5::quiet();
  const std::filesystem::path& file = partial_;
  try {
    file_ = Handle(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), file,
                   "create the file");
    const hid_t root = file_.get();
    createQuflowDatasets(root, n_, file, state_, time_, qtime_);
    const Handle theta(H5Gcreate2(root, "theta", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), file,
                       "create the group theta");
    createQuflowDatasets(theta.get(), n_, file, theta_state_, theta_time_, theta_qtime_);
    const app::hdf5::RowShape number;
    step_ = app::hdf5::createDataset(root, "step", H5T_STD_I64LE, number, file);
    const std::pair<Handle*, const char*> numbers[] = {{&kinetic_, "kinetic_energy"},
                                                       {&magnetic_, "magnetic_energy"},
                                                       {&cross_, "cross_helicity"},
                                                       {&residual_, "residual"},
                                                       {&equilibrium_, "equilibrium_residual"},
                                                       {&drift_, "invariant_drift"}};
    for (const auto& [handle, name] : numbers) {
      *handle = app::hdf5::createDataset(root, name, H5T_IEEE_F64LE, number, file);
    }
    app::hdf5::writeAttribute(root, "alpha", H5T_NATIVE_DOUBLE, &attributes.alpha, file);
    app::hdf5::writeAttribute(root, "h", H5T_NATIVE_DOUBLE, &attributes.h, file);
    app::hdf5::writeAttribute(root, "hbar", H5T_NATIVE_DOUBLE, &attributes.hbar, file);
    app::hdf5::writeAttribute(root, "method", attributes.method, file);
    app::hdf5::writeAttribute(root, "init", attributes.init, file);
    app::hdf5::writeAttribute(root, "theta_init", attributes.theta_init, file);
    app::hdf5::writeAttribute(root, "version", attributes.version, file);
    app::hdf5::writeAttribute(root, "created", attributes.created, file);
  } catch (const app::IoError&) {
    // No half-written file (docs/reference/bad-inputs.md): the file goes if it was created.
    const bool created = static_cast<bool>(file_);
    file_ = Handle();
    std::error_code ignored;
    if (created) std::filesystem::remove(file, ignored);
    throw;
  }
}

void MhdH5::append(const Eigen::VectorXd& omega_w, const Eigen::VectorXd& omega_theta,
                   const MhdFrameNumbers& numbers) {
  if (omega_w.size() != n_ * n_ || omega_theta.size() != n_ * n_) {
    throw app::IoError(partial_.string() + ": a frame of another N than the file's " +
                       std::to_string(n_));
  }
  const auto at = static_cast<hsize_t>(frames_);
  const app::hdf5::RowShape number, omega{1, {static_cast<hsize_t>(n_ * n_), 0}};
  const double qtime = numbers.t / hbar_;
  const std::int64_t step = numbers.step;
  const auto put = [&](const Handle& dataset, const double& value) {
    app::hdf5::appendRow(dataset.get(), H5T_NATIVE_DOUBLE, number, at, &value, partial_);
  };
  app::hdf5::appendRow(state_.get(), H5T_NATIVE_DOUBLE, omega, at, omega_w.data(), partial_);
  app::hdf5::appendRow(theta_state_.get(), H5T_NATIVE_DOUBLE, omega, at, omega_theta.data(),
                       partial_);
  for (const Handle* time : {&time_, &theta_time_}) put(*time, numbers.t);
  for (const Handle* q : {&qtime_, &theta_qtime_}) put(*q, qtime);
  app::hdf5::appendRow(step_.get(), H5T_NATIVE_INT64, number, at, &step, partial_);
  put(kinetic_, numbers.kinetic_energy);
  put(magnetic_, numbers.magnetic_energy);
  put(cross_, numbers.cross_helicity);
  put(residual_, numbers.residual);
  put(equilibrium_, numbers.equilibrium_residual);
  put(drift_, numbers.invariant_drift);
  ++frames_;
}

MhdH5::~MhdH5() {
  if (committed_) return;
  close();
  std::error_code ignored;
  std::filesystem::remove(partial_, ignored);
}

void MhdH5::close() noexcept {
  for (Handle* handle :
       {&state_, &time_, &qtime_, &theta_state_, &theta_time_, &theta_qtime_, &step_, &kinetic_,
        &magnetic_, &cross_, &residual_, &equilibrium_, &drift_, &file_}) {
    *handle = Handle();
  }
}

void MhdH5::commit() {
  app::hdf5::checkStatus(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), partial_, "flush the file");
  close();
  if (std::rename(partial_.c_str(), path_.c_str()) != 0) {
    throw app::IoError(path_.string() + ": cannot rename " + partial_.string() + " onto it");
  }
  committed_ = true;
  app::syncFolderOf(path_);
}

}  // namespace ddb::mhd
