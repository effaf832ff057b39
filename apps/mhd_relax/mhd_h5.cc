#include "mhd_relax/mhd_h5.h"

#include <algorithm>
#include <cstdio>
#include <system_error>
#include <utility>

#include "common/atomic_file.h"
#include "common/exit_status.h"
#include "common/journal_file.h"

namespace ddb::mhd {

namespace {

using app::hdf5::Handle;

/// The per-frame datasets of one number, by name, after the two `state`s.
constexpr const char* kNumbers[] = {
    "time",           "qtime",           "theta/time",     "theta/qtime", "step",
    "kinetic_energy", "magnetic_energy", "cross_helicity", "residual",    "equilibrium_residual",
    "invariant_drift"};

app::hdf5::RowShape omegaRow(long n) { return {1, {static_cast<hsize_t>(n * n), 0}}; }

/// Opens the dataset `name` of `file` and checks that its rows have the shape `row`; returns it
/// and its row count.
std::pair<Handle, hsize_t> openDataset(hid_t file, const char* name, const app::hdf5::RowShape& row,
                                       const std::filesystem::path& path) {
  // H5Lexists of "theta/..." needs the group to exist: it is looked up first.
  if (H5Lexists(file, "theta", H5P_DEFAULT) <= 0 || H5Lexists(file, name, H5P_DEFAULT) <= 0) {
    throw app::IoError(path.string() + ": not an mhd-relax HDF5 file: no dataset " + name);
  }
  Handle dataset(H5Dopen2(file, name, H5P_DEFAULT), path, std::string("open ") + name);
  const Handle space(H5Dget_space(dataset.get()), path, std::string("open ") + name);
  std::array<hsize_t, 2> dims{};
  if (H5Sget_simple_extent_ndims(space.get()) != row.rank + 1) {
    throw app::IoError(path.string() + ": not an mhd-relax HDF5 file: dataset " + name +
                       " has another rank");
  }
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  if (row.rank == 1 && dims[1] != row.dims[0]) {
    throw app::IoError(path.string() + ": dataset " + name + " has rows of another N");
  }
  return {std::move(dataset), dims[0]};
}

}  // namespace

MhdH5::MhdH5(std::filesystem::path path, const MhdH5Attributes& attributes)
    : path_(std::move(path)),
      partial_(app::JournalFile::partialOf(path_)),
      n_(attributes.n),
      hbar_(attributes.hbar) {
  app::hdf5::quiet();
  const std::filesystem::path& file = partial_;
  try {
    file_ = Handle(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), file,
                   "create the file");
    const hid_t root = file_.get();
    const Handle theta(H5Gcreate2(root, "theta", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), file,
                       "create the group theta");
    const std::int64_t n64 = n_;
    for (const hid_t group : {root, theta.get()}) {
      const Handle state =
          app::hdf5::createDataset(group, "state", H5T_IEEE_F64LE, omegaRow(n_), file);
      app::hdf5::writeAttribute(state.get(), "qtype", "shr", file);
      app::hdf5::writeAttribute(group, "N", H5T_NATIVE_INT64, &n64, file);
    }
    for (const char* name : kNumbers) {
      const hid_t type = std::string(name) == "step" ? H5T_STD_I64LE : H5T_IEEE_F64LE;
      app::hdf5::createDataset(root, name, type, app::hdf5::RowShape{}, file);
    }
    app::hdf5::writeAttribute(root, "alpha", H5T_NATIVE_DOUBLE, &attributes.alpha, file);
    app::hdf5::writeAttribute(root, "h", H5T_NATIVE_DOUBLE, &attributes.h, file);
    app::hdf5::writeAttribute(root, "hbar", H5T_NATIVE_DOUBLE, &attributes.hbar, file);
    app::hdf5::writeAttribute(root, "method", attributes.method, file);
    app::hdf5::writeAttribute(root, "init", attributes.init, file);
    app::hdf5::writeAttribute(root, "theta_init", attributes.theta_init, file);
    app::hdf5::writeAttribute(root, "version", attributes.version, file);
    app::hdf5::writeAttribute(root, "created", attributes.created, file);
    openDatasets();
  } catch (const app::IoError&) {
    // No half-written file (docs/reference/bad-inputs.md): the file goes if it was created.
    const bool created = static_cast<bool>(file_);
    close();
    std::error_code ignored;
    if (created) std::filesystem::remove(file, ignored);
    throw;
  }
}

MhdH5::MhdH5(std::filesystem::path path, long n, double hbar, long frames)
    : path_(std::move(path)), partial_(app::JournalFile::partialOf(path_)), n_(n), hbar_(hbar) {
  app::hdf5::quiet();
  const std::filesystem::path from = app::JournalFile::resumeFileOf(path_);
  if (from != partial_ && std::rename(from.c_str(), partial_.c_str()) != 0) {
    throw app::IoError(path_.string() + ": cannot rename it to " + partial_.string());
  }
  if (H5Fis_hdf5(partial_.c_str()) <= 0) {
    throw app::IoError(partial_.string() + ": not an HDF5 file (or missing)");
  }
  file_ = Handle(H5Fopen(partial_.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), partial_, "open the file");
  openDatasets();
  if (frames < 0 || frames > frames_) {
    throw app::IoError(partial_.string() + ": has " + std::to_string(frames_) +
                       " frames, fewer than the " + std::to_string(frames) + " to keep");
  }
  app::hdf5::resize(state_.get(), omegaRow(n_), static_cast<hsize_t>(frames), partial_);
  app::hdf5::resize(theta_state_.get(), omegaRow(n_), static_cast<hsize_t>(frames), partial_);
  for (const Handle* d : {&time_, &qtime_, &theta_time_, &theta_qtime_, &step_, &kinetic_,
                          &magnetic_, &cross_, &residual_, &equilibrium_, &drift_}) {
    app::hdf5::resize(d->get(), app::hdf5::RowShape{}, static_cast<hsize_t>(frames), partial_);
  }
  frames_ = frames;
  flush();
}

void MhdH5::checkResumable(const std::filesystem::path& path, long n, long frames) {
  app::hdf5::quiet();
  const std::filesystem::path file = app::JournalFile::resumeFileOf(path);
  if (H5Fis_hdf5(file.c_str()) <= 0) throw app::IoError(file.string() + ": not an HDF5 file");
  const Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), file, "open the file");
  hsize_t shortest = openDataset(h5.get(), "state", omegaRow(n), file).second;
  shortest = std::min(shortest, openDataset(h5.get(), "theta/state", omegaRow(n), file).second);
  for (const char* name : kNumbers) {
    shortest = std::min(shortest, openDataset(h5.get(), name, app::hdf5::RowShape{}, file).second);
  }
  if (shortest < static_cast<hsize_t>(frames)) {
    throw app::IoError(file.string() + ": has " + std::to_string(shortest) +
                       " frames, fewer than the " + std::to_string(frames) +
                       " its checkpoint recorded");
  }
}

void MhdH5::openDatasets() {
  const hid_t file = file_.get();
  auto [state, rows] = openDataset(file, "state", omegaRow(n_), partial_);
  state_ = std::move(state);
  hsize_t shortest = rows;
  const auto open = [&](Handle& into, const char* name, const app::hdf5::RowShape& row) {
    auto [dataset, count] = openDataset(file, name, row, partial_);
    into = std::move(dataset);
    shortest = std::min(shortest, count);
  };
  open(theta_state_, "theta/state", omegaRow(n_));
  Handle* numbers[] = {&time_,     &qtime_, &theta_time_, &theta_qtime_, &step_, &kinetic_,
                       &magnetic_, &cross_, &residual_,   &equilibrium_, &drift_};
  for (std::size_t i = 0; i < std::size(kNumbers); ++i) {
    open(*numbers[i], kNumbers[i], app::hdf5::RowShape{});
  }
  frames_ = static_cast<long>(shortest);
}

void MhdH5::append(const Eigen::VectorXd& omega_w, const Eigen::VectorXd& omega_theta,
                   const MhdFrameNumbers& numbers) {
  if (omega_w.size() != n_ * n_ || omega_theta.size() != n_ * n_) {
    throw app::IoError(partial_.string() + ": a frame of another N than the file's " +
                       std::to_string(n_));
  }
  const auto at = static_cast<hsize_t>(frames_);
  const app::hdf5::RowShape number;
  const double qtime = numbers.t / hbar_;
  const std::int64_t step = numbers.step;
  const auto put = [&](const Handle& dataset, const double& value) {
    app::hdf5::appendRow(dataset.get(), H5T_NATIVE_DOUBLE, number, at, &value, partial_);
  };
  app::hdf5::appendRow(state_.get(), H5T_NATIVE_DOUBLE, omegaRow(n_), at, omega_w.data(), partial_);
  app::hdf5::appendRow(theta_state_.get(), H5T_NATIVE_DOUBLE, omegaRow(n_), at, omega_theta.data(),
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

void MhdH5::close() noexcept {
  for (Handle* handle :
       {&state_, &time_, &qtime_, &theta_state_, &theta_time_, &theta_qtime_, &step_, &kinetic_,
        &magnetic_, &cross_, &residual_, &equilibrium_, &drift_, &file_}) {
    *handle = Handle();
  }
}

void MhdH5::flush() {
  app::hdf5::checkStatus(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), partial_, "flush the file");
}

void MhdH5::commit() {
  flush();
  close();
  if (std::rename(partial_.c_str(), path_.c_str()) != 0) {
    throw app::IoError(path_.string() + ": cannot rename " + partial_.string() + " onto it");
  }
  app::syncFolderOf(path_);
}

}  // namespace ddb::mhd
