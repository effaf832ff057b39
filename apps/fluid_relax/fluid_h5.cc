#include "fluid_relax/fluid_h5.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <tuple>

#include "common/exit_status.h"

namespace ddb::fluid {

namespace {

using app::hdf5::appendRow;
using app::hdf5::check;
using app::hdf5::checkStatus;
using app::hdf5::createDataset;
using app::hdf5::Handle;
using app::hdf5::resize;
using app::hdf5::RowShape;

/// The row shapes of fluid.hdf5's datasets at resolution N.
struct Shapes {
  RowShape number, state, matrix, spectrum, grid;
  explicit Shapes(long n)
      : state{1, {static_cast<hsize_t>(n * n), 0}},
        matrix{2, {static_cast<hsize_t>(n), static_cast<hsize_t>(n)}},
        spectrum{1, {static_cast<hsize_t>(n), 0}},
        grid{2, {static_cast<hsize_t>(n), static_cast<hsize_t>(2 * n - 1)}} {}
};

/// The field diagnostics' datasets of one number per frame.
constexpr std::array<const char*, 3> kFieldNumbers{"gamma", "enstrophy_steady",
                                                   "enstrophy_remainder"};

/// Opens the dataset `name` and checks that its rows have the shape `row`; returns it and
/// its row count.
std::pair<Handle, hsize_t> openDataset(hid_t file, const char* name, const RowShape& row,
                                       const std::filesystem::path& path) {
  const std::string what = std::string("open the dataset ") + name;
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0) {
    throw app::IoError(path.string() + ": not a fluid-relax HDF5 file: no dataset " + name);
  }
  Handle dataset(H5Dopen2(file, name, H5P_DEFAULT), path, what);
  const Handle space(H5Dget_space(dataset.get()), path, what);
  std::array<hsize_t, 3> dims{};
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank != row.rank + 1) {
    throw app::IoError(path.string() + ": not a fluid-relax HDF5 file: dataset " + name +
                       " has rank " + std::to_string(rank));
  }
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  for (int d = 0; d < row.rank; ++d) {
    if (dims[static_cast<std::size_t>(d) + 1] != row.dims[static_cast<std::size_t>(d)]) {
      throw app::IoError(path.string() + ": not a fluid-relax HDF5 file: dataset " + name +
                         " has rows of another shape than N = " + std::to_string(row.dims[0]));
    }
  }
  return {std::move(dataset), dims[0]};
}

double readDoubleAttribute(hid_t file, const char* name, const std::filesystem::path& path) {
  double value = 0.0;
  app::hdf5::readAttribute(file, name, H5T_NATIVE_DOUBLE, &value, path);
  return value;
}

}  // namespace

FluidH5::FluidH5(std::filesystem::path path, long n, double hbar)
    : path_(std::move(path)), n_(n), hbar_(hbar), complex_(app::hdf5::complexType(path_)) {
  row_major_.resize(n, n);
}

FluidH5 FluidH5::create(const std::filesystem::path& path, const FluidH5Attributes& attributes) {
  app::hdf5::quiet();
  FluidH5 h5(path, attributes.n, attributes.hbar);
  try {
    h5.file_ = Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), path,
                      "create the file");
    h5.writeLayout(attributes);
  } catch (const app::IoError&) {
    // No half-written file (docs/reference/bad-inputs.md): the file goes if it was created.
    const bool created = static_cast<bool>(h5.file_);
    h5.file_ = Handle();
    std::error_code ignored;
    if (created) std::filesystem::remove(path, ignored);
    throw;
  }
  return h5;
}

void FluidH5::writeLayout(const FluidH5Attributes& attributes) {
  const hid_t file = file_.get();
  const std::filesystem::path& path = path_;
  const Shapes shapes(n_);
  const Handle state = createDataset(file, "state", H5T_IEEE_F64LE, shapes.state, path);
  app::hdf5::writeAttribute(state.get(), "qtype", "shr", path);
  createDataset(file, "mat", complex_.get(), shapes.matrix, path);
  for (const char* name :
       {"time", "qtime", "energy_euler", "enstrophy", "commutator_norm", "spectrum_drift"}) {
    createDataset(file, name, H5T_IEEE_F64LE, shapes.number, path);
  }
  createDataset(file, "step", H5T_STD_I64LE, shapes.number, path);
  for (const char* name : kFieldNumbers) {
    createDataset(file, name, H5T_IEEE_F64LE, shapes.number, path);
  }
  for (const char* name : {"energy_spectrum", "enstrophy_spectrum"}) {
    createDataset(file, name, H5T_IEEE_F64LE, shapes.spectrum, path);
  }
  const Handle grid = createDataset(file, "fun", H5T_IEEE_F64LE, shapes.grid, path);
  app::hdf5::writeAttribute(grid.get(), "qtype", "fun", path);

  const std::int64_t n64 = attributes.n;
  app::hdf5::writeAttribute(file, "N", H5T_NATIVE_INT64, &n64, path);
  app::hdf5::writeAttribute(file, "alpha", H5T_NATIVE_DOUBLE, &attributes.alpha, path);
  app::hdf5::writeAttribute(file, "h", H5T_NATIVE_DOUBLE, &attributes.h, path);
  app::hdf5::writeAttribute(file, "hbar", H5T_NATIVE_DOUBLE, &attributes.hbar, path);
  app::hdf5::writeAttribute(file, "method", attributes.method, path);
  app::hdf5::writeAttribute(file, "init", attributes.init, path);
  if (attributes.seed) {
    app::hdf5::writeAttribute(file, "seed", H5T_NATIVE_UINT64, &*attributes.seed, path);
  } else {
    app::hdf5::writeAttribute(file, "init_file", attributes.init_file, path);
  }
  app::hdf5::writeAttribute(file, "version", attributes.version, path);
  app::hdf5::writeAttribute(file, "created", attributes.created, path);
  openDatasets();
  flush();
}

FluidH5 FluidH5::reopen(const std::filesystem::path& path, long frames, bool fields) {
  app::hdf5::quiet();
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    throw app::IoError(path.string() + ": not an HDF5 file (or missing)");
  }
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), path, "open the file");
  const auto n = static_cast<long>(readDoubleAttribute(file.get(), "N", path));
  FluidH5 h5(path, n, readDoubleAttribute(file.get(), "hbar", path));
  h5.file_ = std::move(file);
  h5.fields_ = fields;
  h5.openDatasets();
  if (frames < 0 || static_cast<hsize_t>(frames) > static_cast<hsize_t>(h5.frames_)) {
    throw app::IoError(path.string() + ": has " + std::to_string(h5.frames_) +
                       " frames, fewer than the " + std::to_string(frames) + " to keep");
  }
  const Shapes shapes(n);
  resize(h5.state_.get(), shapes.state, static_cast<hsize_t>(frames), path);
  resize(h5.mat_.get(), shapes.matrix, static_cast<hsize_t>(frames), path);
  for (const Handle* d : {&h5.time_, &h5.qtime_, &h5.step_, &h5.energy_, &h5.enstrophy_,
                          &h5.commutator_, &h5.drift_}) {
    resize(d->get(), shapes.number, static_cast<hsize_t>(frames), path);
  }
  if (fields) {
    for (const Handle* d : {&h5.gamma_, &h5.enstrophy_steady_, &h5.enstrophy_remainder_}) {
      resize(d->get(), shapes.number, static_cast<hsize_t>(frames), path);
    }
    resize(h5.energy_spectrum_.get(), shapes.spectrum, static_cast<hsize_t>(frames), path);
    resize(h5.enstrophy_spectrum_.get(), shapes.spectrum, static_cast<hsize_t>(frames), path);
    resize(h5.grid_.get(), shapes.grid, static_cast<hsize_t>(frames), path);
  }
  h5.frames_ = frames;
  h5.flush();
  return h5;
}

void FluidH5::checkResumable(const std::filesystem::path& path, const FluidH5Attributes& expected,
                             long frames, bool fields) {
  app::hdf5::quiet();
  if (H5Fis_hdf5(path.c_str()) <= 0) throw app::IoError(path.string() + ": not an HDF5 file");
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path, "open the file");
  const auto differs = [&](const char* name, const std::string& found, const std::string& run) {
    if (found != run) {
      throw app::IoError(path.string() + " is another run's: its " + name + " is " + found +
                         ", this run's " + run);
    }
  };
  std::int64_t n = 0;
  app::hdf5::readAttribute(file.get(), "N", H5T_NATIVE_INT64, &n, path);
  differs("N", std::to_string(n), std::to_string(expected.n));
  // The numbers as their bytes: the file holds the run's doubles exactly.
  for (const auto& [name, value] : {std::pair{"alpha", expected.alpha}, {"h", expected.h}}) {
    const double found = readDoubleAttribute(file.get(), name, path);
    if (std::memcmp(&found, &value, sizeof value) != 0) {
      differs(name, fmt::format("{}", found), fmt::format("{}", value));
    }
  }
  differs("method", app::hdf5::readStringAttribute(file.get(), "method", path), expected.method);
  differs("init", app::hdf5::readStringAttribute(file.get(), "init", path), expected.init);
  if (expected.seed) {
    std::uint64_t seed = 0;
    app::hdf5::readAttribute(file.get(), "seed", H5T_NATIVE_UINT64, &seed, path);
    differs("seed", std::to_string(seed), std::to_string(*expected.seed));
  } else {
    differs("init_file", app::hdf5::readStringAttribute(file.get(), "init_file", path),
            expected.init_file);
  }
  FluidH5 h5(path, static_cast<long>(n), 0.0);
  h5.file_ = std::move(file);
  h5.fields_ = fields;
  h5.openDatasets();
  if (h5.frames_ < frames) {
    throw app::IoError(path.string() + ": has " + std::to_string(h5.frames_) +
                       " frames, fewer than the " + std::to_string(frames) +
                       " the checkpoint recorded");
  }
}

void FluidH5::openDatasets() {
  const hid_t file = file_.get();
  const Shapes shapes(n_);
  hsize_t rows = 0;
  std::tie(state_, rows) = openDataset(file, "state", shapes.state, path_);
  // A run killed within a frame can leave datasets one row apart: the frames are the
  // rows all of them have.
  const auto open = [&](Handle& into, const char* name, const RowShape& row) {
    hsize_t length = 0;
    std::tie(into, length) = openDataset(file, name, row, path_);
    rows = std::min(rows, length);
  };
  open(mat_, "mat", shapes.matrix);
  open(time_, "time", shapes.number);
  open(qtime_, "qtime", shapes.number);
  open(step_, "step", shapes.number);
  open(energy_, "energy_euler", shapes.number);
  open(enstrophy_, "enstrophy", shapes.number);
  open(commutator_, "commutator_norm", shapes.number);
  open(drift_, "spectrum_drift", shapes.number);
  if (fields_) {
    open(gamma_, kFieldNumbers[0], shapes.number);
    open(enstrophy_steady_, kFieldNumbers[1], shapes.number);
    open(enstrophy_remainder_, kFieldNumbers[2], shapes.number);
    open(energy_spectrum_, "energy_spectrum", shapes.spectrum);
    open(enstrophy_spectrum_, "enstrophy_spectrum", shapes.spectrum);
    open(grid_, "fun", shapes.grid);
  }
  frames_ = static_cast<long>(rows);
}

void FluidH5::append(const FluidH5Frame& frame) {
  if (frame.W.rows() != n_ || frame.W.cols() != n_ || frame.omega.size() != n_ * n_) {
    throw app::IoError(path_.string() + ": a frame of another N than the file's " +
                       std::to_string(n_));
  }
  const auto at = static_cast<hsize_t>(frames_);
  const Shapes shapes(n_);
  const RowShape& number = shapes.number;
  row_major_ = frame.W;
  const std::int64_t step = frame.step;
  const double qtime = frame.t / hbar_;
  appendRow(state_.get(), H5T_NATIVE_DOUBLE, shapes.state, at, frame.omega.data(), path_);
  appendRow(mat_.get(), complex_.get(), shapes.matrix, at, row_major_.data(), path_);
  appendRow(time_.get(), H5T_NATIVE_DOUBLE, number, at, &frame.t, path_);
  appendRow(qtime_.get(), H5T_NATIVE_DOUBLE, number, at, &qtime, path_);
  appendRow(step_.get(), H5T_NATIVE_INT64, number, at, &step, path_);
  appendRow(energy_.get(), H5T_NATIVE_DOUBLE, number, at, &frame.energy, path_);
  appendRow(enstrophy_.get(), H5T_NATIVE_DOUBLE, number, at, &frame.enstrophy, path_);
  appendRow(commutator_.get(), H5T_NATIVE_DOUBLE, number, at, &frame.commutator_norm, path_);
  appendRow(drift_.get(), H5T_NATIVE_DOUBLE, number, at, &frame.spectrum_drift, path_);
  if (fields_) {
    const FluidH5Fields* f = frame.fields;
    if (f == nullptr || f->energy_spectrum.size() != n_ || f->enstrophy_spectrum.size() != n_ ||
        f->grid.rows() != n_ || f->grid.cols() != 2 * n_ - 1) {
      throw std::logic_error("FluidH5::append: a frame without the file's field diagnostics");
    }
    appendRow(gamma_.get(), H5T_NATIVE_DOUBLE, number, at, &f->gamma, path_);
    appendRow(enstrophy_steady_.get(), H5T_NATIVE_DOUBLE, number, at, &f->enstrophy_steady, path_);
    appendRow(enstrophy_remainder_.get(), H5T_NATIVE_DOUBLE, number, at, &f->enstrophy_remainder,
              path_);
    appendRow(energy_spectrum_.get(), H5T_NATIVE_DOUBLE, shapes.spectrum, at,
              f->energy_spectrum.data(), path_);
    appendRow(enstrophy_spectrum_.get(), H5T_NATIVE_DOUBLE, shapes.spectrum, at,
              f->enstrophy_spectrum.data(), path_);
    // θ down the rows, φ along them: row-major in the file, as quflow's fun arrays.
    grid_row_major_ = f->grid;
    appendRow(grid_.get(), H5T_NATIVE_DOUBLE, shapes.grid, at, grid_row_major_.data(), path_);
  }
  ++frames_;
}

void FluidH5::flush() {
  checkStatus(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), path_, "flush the file");
}

}  // namespace ddb::fluid
