// fluid-relax's HDF5 writer (apps/fluid_relax/fluid_h5.h, docs/reference/command-lines-and-files.md
// "fluid.hdf5"): what append() writes is read back through the HDF5 C API (the frames'
// values are made up here, each distinct); reopen(path, frames) keeps the first frames
// and appends after them, and refuses files it cannot continue, naming them. The app's
// own file is checked against its CSV files with h5py (tests/python/test_fluid_h5.py).
#include <gmock/gmock.h>

#include <complex>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app_test_support.h"
#include "common/exit_status.h"
#include "fluid_relax/fluid_h5.h"
#include "h5_test_support.h"

namespace fluid_h5_tests {

using ddb::app::IoError;
using ddb::fluid::FluidH5;
using ddb::fluid::FluidH5Attributes;
using ddb::test::readAll;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

constexpr long kN = 3;

FluidH5Attributes attributes() {
  FluidH5Attributes a;
  a.n = kN;
  a.alpha = 0.5;
  a.h = 0.01;
  a.hbar = 2.0 / std::sqrt(double(kN * kN - 1));
  a.method = "ddb-cay";
  a.init = "random";
  a.seed = 7;
  a.version = "test";
  a.created = ddb::app::hdf5::utcNow();
  return a;
}

/// Frame `step`'s matrix: W(j, k) = step + 10 j + 100 k + i (j − k), every entry distinct.
Eigen::MatrixXcd frameMatrix(long step) {
  Eigen::MatrixXcd W(kN, kN);
  for (Eigen::Index j = 0; j < kN; ++j) {
    for (Eigen::Index k = 0; k < kN; ++k) {
      W(j, k) = {double(step + 10 * j + 100 * k), double(j - k)};
    }
  }
  return W;
}

/// Frame `step`'s grid: f(j, k) = step + 10 j + 100 k.
Eigen::MatrixXd frameGrid(long step) {
  Eigen::MatrixXd f(kN, 2 * kN - 1);
  for (Eigen::Index j = 0; j < f.rows(); ++j) {
    for (Eigen::Index k = 0; k < f.cols(); ++k) f(j, k) = double(step + 10 * j + 100 * k);
  }
  return f;
}

void appendFrame(FluidH5& h5, long step) {
  const Eigen::MatrixXcd W = frameMatrix(step);
  const Eigen::VectorXd omega = Eigen::VectorXd::Constant(kN * kN, double(step));
  const Eigen::VectorXd energy = Eigen::VectorXd::LinSpaced(kN, double(step), double(step) + 1.0);
  const Eigen::VectorXd enstrophy = 2.0 * energy;
  const Eigen::MatrixXd grid = frameGrid(step);
  const ddb::fluid::FluidH5Fields fields{5.0 + step, energy,     enstrophy,
                                         6.0 + step, 7.0 + step, grid};
  h5.append({step, 0.5 * double(step), W, omega, 1.0 + step, 2.0 + step, 3.0 + step, 4.0 + step,
             h5.fields() ? &fields : nullptr});
}

fs::path freshFile(const std::string& name) {
  const fs::path dir = ddb::test::freshFolder("fluid_h5_test_", name);
  fs::create_directories(dir);
  return dir / "fluid.hdf5";
}

TEST(FluidH5, AppendWritesEachFrameAsGiven) {
  const fs::path path = freshFile("append");
  {
    FluidH5 h5 = FluidH5::create(path, attributes());
    for (long step = 0; step < 4; ++step) appendFrame(h5, 2 * step);
    EXPECT_EQ(h5.frames(), 4);
  }
  hsize_t rows = 0;
  const auto steps = readAll<long long>(path, "step", H5T_NATIVE_LLONG, &rows);
  EXPECT_EQ(rows, 4u);
  EXPECT_EQ(steps, (std::vector<long long>{0, 2, 4, 6}));
  const double hbar = attributes().hbar;
  const auto time = readAll<double>(path, "time", H5T_NATIVE_DOUBLE, &rows);
  const auto qtime = readAll<double>(path, "qtime", H5T_NATIVE_DOUBLE, &rows);
  const auto energy = readAll<double>(path, "energy_euler", H5T_NATIVE_DOUBLE, &rows);
  const auto drift = readAll<double>(path, "spectrum_drift", H5T_NATIVE_DOUBLE, &rows);
  for (std::size_t f = 0; f < 4; ++f) {
    EXPECT_EQ(time[f], 0.5 * double(steps[f]));
    EXPECT_DOUBLE_EQ(qtime[f], 0.5 * double(steps[f]) / hbar);
    EXPECT_EQ(energy[f], 1.0 + double(steps[f]));
    EXPECT_EQ(drift[f], 4.0 + double(steps[f]));
  }
  // mat[f][j][k] = W(j, k): row-major on disk, h5py's complex as {r, i}.
  const hid_t complex = ddb::test::complexType();
  const auto mat = readAll<std::complex<double>>(path, "mat", complex, &rows);
  H5Tclose(complex);
  ASSERT_EQ(mat.size(), std::size_t(4 * kN * kN));
  for (std::size_t f = 0; f < 4; ++f) {
    const Eigen::MatrixXcd W = frameMatrix(steps[f]);
    for (Eigen::Index j = 0; j < kN; ++j) {
      for (Eigen::Index k = 0; k < kN; ++k) {
        EXPECT_EQ(mat[f * kN * kN + std::size_t(j * kN + k)], W(j, k)) << f << " " << j << k;
      }
    }
  }
  const auto state = readAll<double>(path, "state", H5T_NATIVE_DOUBLE, &rows);
  ASSERT_EQ(state.size(), std::size_t(4 * kN * kN));
  EXPECT_EQ(state[3 * kN * kN + 5], 6.0);
  // The field diagnostics: numbers, spectra of N values and grids of N × (2N − 1), row-major.
  const auto gamma = readAll<double>(path, "gamma", H5T_NATIVE_DOUBLE, &rows);
  const auto steady = readAll<double>(path, "enstrophy_steady", H5T_NATIVE_DOUBLE, &rows);
  const auto remainder = readAll<double>(path, "enstrophy_remainder", H5T_NATIVE_DOUBLE, &rows);
  const auto spectrum = readAll<double>(path, "enstrophy_spectrum", H5T_NATIVE_DOUBLE, &rows);
  const auto fun = readAll<double>(path, "fun", H5T_NATIVE_DOUBLE, &rows);
  ASSERT_EQ(spectrum.size(), std::size_t(4 * kN));
  ASSERT_EQ(fun.size(), std::size_t(4 * kN * (2 * kN - 1)));
  for (std::size_t f = 0; f < 4; ++f) {
    const double step = double(steps[f]);
    EXPECT_EQ(gamma[f], 5.0 + step);
    EXPECT_EQ(steady[f], 6.0 + step);
    EXPECT_EQ(remainder[f], 7.0 + step);
    EXPECT_EQ(spectrum[f * kN + kN - 1], 2.0 * (step + 1.0));
    const std::size_t j = 2, k = 3;
    EXPECT_EQ(fun[f * kN * (2 * kN - 1) + j * (2 * kN - 1) + k], step + 10.0 * j + 100.0 * k);
  }
}

TEST(FluidH5, ReopenShrinksToFramesAndAppendsAfterThem) {
  const fs::path path = freshFile("reopen");
  {
    FluidH5 h5 = FluidH5::create(path, attributes());
    for (long step = 0; step < 5; ++step) appendFrame(h5, step);
  }
  {
    FluidH5 h5 = FluidH5::reopen(path, 3, true);
    EXPECT_EQ(h5.frames(), 3);
    appendFrame(h5, 99);
    EXPECT_EQ(h5.frames(), 4);
    h5.flush();
  }
  hsize_t rows = 0;
  EXPECT_EQ(readAll<long long>(path, "step", H5T_NATIVE_LLONG, &rows),
            (std::vector<long long>{0, 1, 2, 99}));
  for (const char* name : {"time", "qtime", "energy_euler", "enstrophy", "commutator_norm",
                           "spectrum_drift", "state"}) {
    readAll<double>(path, name, H5T_NATIVE_DOUBLE, &rows);
    EXPECT_EQ(rows, 4u) << name;
  }
  const auto time = readAll<double>(path, "time", H5T_NATIVE_DOUBLE, &rows);
  EXPECT_EQ(time, (std::vector<double>{0.0, 0.5, 1.0, 49.5}));
  EXPECT_EQ(FluidH5::reopen(path, 0, true).frames(), 0);
}

TEST(FluidH5, ReopenCutsDatasetsOfUnequalLengthsAlike) {
  // A run killed within a frame: `state` and `mat` have a row more than the rest.
  const fs::path path = freshFile("unequal");
  {
    FluidH5 h5 = FluidH5::create(path, attributes());
    for (long step = 0; step < 3; ++step) appendFrame(h5, step);
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hsize_t state_rows[] = {4, kN * kN}, mat_rows[] = {4, kN, kN};
  const hid_t state = H5Dopen2(file, "state", H5P_DEFAULT),
              mat = H5Dopen2(file, "mat", H5P_DEFAULT);
  H5Dset_extent(state, state_rows);
  H5Dset_extent(mat, mat_rows);
  H5Dclose(state);
  H5Dclose(mat);
  H5Fclose(file);
  EXPECT_THAT([&] { FluidH5::reopen(path, 4, true); },
              testing::ThrowsMessage<IoError>(HasSubstr(path.string() + ": has 3 frames")));
  {
    FluidH5 h5 = FluidH5::reopen(path, 3, true);
    appendFrame(h5, 7);
  }
  hsize_t rows = 0;
  for (const char* name : {"state", "time", "spectrum_drift"}) {
    readAll<double>(path, name, H5T_NATIVE_DOUBLE, &rows);
    EXPECT_EQ(rows, 4u) << name;
  }
  EXPECT_EQ(readAll<long long>(path, "step", H5T_NATIVE_LLONG, &rows),
            (std::vector<long long>{0, 1, 2, 7}));
  const auto omega = readAll<double>(path, "state", H5T_NATIVE_DOUBLE, &rows);
  EXPECT_EQ(omega[3 * kN * kN], 7.0);
}

TEST(FluidH5, ReopenRefusesFilesItCannotContinue) {
  const fs::path path = freshFile("refuse");
  {
    FluidH5 h5 = FluidH5::create(path, attributes());
    appendFrame(h5, 0);
    appendFrame(h5, 1);
  }
  testing::internal::CaptureStderr();
  EXPECT_THAT([&] { FluidH5::reopen(path, 3, true); },
              testing::ThrowsMessage<IoError>(HasSubstr(path.string() + ": has 2 frames")));
  const fs::path text = path.parent_path() / "notes.hdf5";
  std::ofstream(text) << "not HDF5\n";
  EXPECT_THAT([&] { FluidH5::reopen(text, 0, true); },
              testing::ThrowsMessage<IoError>(HasSubstr(text.string() + ": not an HDF5 file")));
  const fs::path missing = path.parent_path() / "missing.hdf5";
  EXPECT_THAT([&] { FluidH5::reopen(missing, 0, true); },
              testing::ThrowsMessage<IoError>(HasSubstr(missing.string())));
  // An HDF5 file of another layout.
  const fs::path other = path.parent_path() / "other.hdf5";
  H5Fclose(H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  EXPECT_THAT(
      [&] { FluidH5::reopen(other, 0, true); },
      testing::ThrowsMessage<IoError>(HasSubstr(other.string() + ": not a fluid-relax HDF5 file")));
  // HDF5's own error stack is not printed: the message above is the only report.
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(FluidH5, CreateFailureNamesTheFileAndLeavesNothing) {
  const fs::path path = freshFile("create") / "no-such-folder" / "fluid.hdf5";
  testing::internal::CaptureStderr();
  EXPECT_THAT([&] { FluidH5::create(path, attributes()); },
              testing::ThrowsMessage<IoError>(HasSubstr(path.string() + ": cannot create")));
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_FALSE(fs::exists(path));
  // A folder of the file's name is the user's: refused, and left alone.
  const fs::path folder = freshFile("folder");
  fs::create_directories(folder);
  EXPECT_THAT([&] { FluidH5::create(folder, attributes()); },
              testing::ThrowsMessage<IoError>(HasSubstr(folder.string() + ": cannot create")));
  EXPECT_TRUE(fs::is_directory(folder));
}

}  // namespace fluid_h5_tests
