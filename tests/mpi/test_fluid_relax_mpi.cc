// fluid-relax-mpi end to end (docs/design/distributed.md, "fluid-relax-mpi") against fluid-relax,
// the serial app: on 1, 2 and 4 ranks (oversubscribed; also on the grid shapes --grid-rows
// asks for), N = 16 and 33 with block sizes that do not divide N, α = 0, 0.5 and −0.5, 100 steps:
// W_final.csv equal to 1e-13 relative, history.csv row by row and summary.json key by key equal to
// rounding (the Legendre iteration counts up to a stopping test decided the other way at the
// tolerance's edge);
// --until-steady stops at the same step; --adaptive takes the serial app's steps (the same h,
// the same rejections) on 1, 2 and 4 ranks, to --steps and to --t-end; bad input is refused
// by every rank with fluid-relax's message, once, exit status 2 and nothing written. Checkpoints
// (docs/design/distributed.md, "Checkpoints"): a run stopped and resumed on the same ranks and
// block size ends with every file byte for byte the uninterrupted run's (fluid.hdf5's datasets bit
// for bit); either app resumes the other's checkpoint and agrees with the uninterrupted serial run
// to rounding; --h5 writes fluid-relax's fluid.hdf5 to rounding; bad resumes are refused; a
// SIGTERM to one rank leaves a checkpoint and exit status 143, and the resumed run is the
// uninterrupted one's to the bit.
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "app_test_support.h"
#include "h5_test_support.h"

namespace ddb::test {
namespace {

const RunEnvironment kMpiEnvironment{kMpiVariables, 240};

AppResult runMpi(int ranks, const std::string& arguments) {
  return runProgram(MPIEXEC_PATH,
                    "-n " + std::to_string(ranks) + " " + FLUID_RELAX_MPI_PATH + " " + arguments,
                    kMpiEnvironment);
}

// The app's messages on stderr: one, not one per rank, for an outcome all ranks share.
std::size_t messageCount(const std::string& error) {
  const std::string prefix = "fluid-relax-mpi: ";
  std::size_t count = 0;
  for (std::size_t at = error.find(prefix); at != std::string::npos;
       at = error.find(prefix, at + 1)) {
    ++count;
  }
  return count;
}

double relative(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale == 0.0 ? 0.0 : std::abs(a - b) / scale;
}

double matrixDistance(const std::vector<std::vector<double>>& a,
                      const std::vector<std::vector<double>>& b) {
  double difference = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    for (std::size_t j = 0; j < b[i].size(); ++j) {
      difference += std::pow(a[i][j] - b[i][j], 2);
      norm += b[i][j] * b[i][j];
    }
  }
  return std::sqrt(difference / norm);
}

// How far apart two runs' spectrum drifts may be when the method leaves the orbit (rk4: 1e-7,
// lobatto3c: 8e-10 in these runs). The drift is ‖λ − λ₀‖₂/‖λ₀‖₂, λ the spectrum; by the
// Hoffman–Wielandt inequality two states' spectra differ by at most ‖ΔW‖_F, and ‖λ₀‖₂ = ‖W₀‖_F,
// so the drifts differ by at most W_final's bound on ‖ΔW‖_F/‖W‖_F, 1e-13 (‖W‖_F stays within
// rounding of ‖W₀‖_F here), plus the two eigensolvers' rounding: twice that bound.
constexpr double kDriftDifference = 2e-13;

// The history columns t, energy, enstrophy, commutator_norm, spectrum_drift, h, residual:
// the drift is rounding (≈ 1e-15) in both runs of a method that keeps the Casimirs and is
// compared absolutely; another method's drift is a difference of spectra of states equal to
// 1e-13 (kDriftDifference).
void expectSameHistory(const fs::path& mpi, const fs::path& serial, bool keeps_casimirs = true) {
  std::string mpi_header, serial_header;
  const auto a = readCsv(mpi / "history.csv", &mpi_header);
  const auto b = readCsv(serial / "history.csv", &serial_header);
  EXPECT_EQ(mpi_header, serial_header);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < b.size(); ++k) {
    ASSERT_EQ(a[k].size(), b[k].size());
    EXPECT_EQ(a[k][0], b[k][0]) << "t, row " << k;
    EXPECT_EQ(a[k][5], b[k][5]) << "h, row " << k;
    for (const std::size_t column : {1, 2, 3, 6}) {
      EXPECT_LT(relative(a[k][column], b[k][column]), 1e-11)
          << "column " << column << ", row " << k;
    }
    if (keeps_casimirs) {
      EXPECT_LT(a[k][4], 1e-13) << "spectrum drift, row " << k;
    } else {
      EXPECT_NEAR(a[k][4], b[k][4], kDriftDifference) << "spectrum drift, row " << k;
    }
  }
}

// rows: the process grid's rows asked for, 0 for the default shape.
void expectSameSummary(const fs::path& mpi, const fs::path& serial, int ranks, int rows = 0,
                       bool keeps_casimirs = true) {
  const auto a = readJson(mpi / "summary.json");
  const auto b = readJson(serial / "summary.json");
  const std::set<std::string> rounding = {"energy_initial",
                                          "energy_final",
                                          "enstrophy_initial",
                                          "enstrophy",
                                          "commutator_initial",
                                          "commutator_final",
                                          "residual_final",
                                          "alpha",
                                          "h",
                                          "t_end",
                                          "h_final"};
  for (const auto& [key, value] : b.items()) {
    ASSERT_TRUE(a.contains(key)) << key;
    if (key == "runtime_s") continue;
    if (key == "spectrum_drift_max" && keeps_casimirs) {
      EXPECT_LT(a[key].get<double>(), 1e-13);
    } else if (key == "spectrum_drift_max") {
      EXPECT_NEAR(a[key].get<double>(), value.get<double>(), kDriftDifference);
    } else if ((key == "iterations_mean" || key == "iterations_max") && value.is_null()) {
      EXPECT_TRUE(a[key].is_null()) << key << " (a method that solves nothing)";
    } else if (key == "iterations_mean") {
      EXPECT_LT(relative(a[key].get<double>(), value.get<double>()), 0.03) << key;
    } else if (key == "iterations_max") {
      EXPECT_LE(std::abs(a[key].get<long>() - value.get<long>()), 1) << key;
    } else if (rounding.count(key) > 0 && value.is_number()) {
      EXPECT_LT(relative(a[key].get<double>(), value.get<double>()), 1e-11) << key;
    } else {
      EXPECT_EQ(a[key], value) << key;
    }
  }
  EXPECT_EQ(a["mpi_ranks"], ranks);
  if (rows == 0) rows = ranks == 4 ? 2 : ranks;  // the default grid: rows ≥ cols
  EXPECT_EQ(a["process_grid"], nlohmann::ordered_json::array({rows, ranks / rows}));
}

class FluidRelaxMpiTest : public testing::TestWithParam<std::tuple<int, int, std::string>> {};

TEST_P(FluidRelaxMpiTest, WritesWhatTheSerialAppWrites) {
  const auto [ranks, n, alpha] = GetParam();
  const std::string name = std::to_string(ranks) + "_" + std::to_string(n) + "_" + alpha;
  const fs::path serial = freshFolder("ddb_mpi_serial_", name);
  const fs::path mpi = freshFolder("ddb_mpi_", name);
  const std::string common =
      "--n " + std::to_string(n) + " --alpha " + alpha + " --steps 100 --every 10 --quiet";
  const AppResult s = runProgram(FLUID_RELAX_PATH, common + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.output;
  const AppResult m = runMpi(ranks, common + " --block 5 --out " + mpi.string());
  ASSERT_EQ(m.status, 0) << m.output;
  EXPECT_LT(matrixDistance(readCsv(mpi / "W_final.csv", nullptr),
                           readCsv(serial / "W_final.csv", nullptr)),
            1e-13);
  expectSameHistory(mpi, serial);
  expectSameSummary(mpi, serial, ranks);
  EXPECT_EQ(readJson(mpi / "summary.json")["block_size"], 5);
  for (const char* file : {"omega_initial.csv", "omega_final.csv"}) {
    std::string mpi_header, serial_header;
    const auto a = readCsv(mpi / file, &mpi_header), b = readCsv(serial / file, &serial_header);
    EXPECT_EQ(mpi_header, serial_header) << file;
    ASSERT_EQ(a.size(), b.size()) << file;
    EXPECT_LT(matrixDistance(a, b), 1e-12) << file;
  }
  fs::remove_all(serial);
  fs::remove_all(mpi);
}

INSTANTIATE_TEST_SUITE_P(RanksSizesAlphas, FluidRelaxMpiTest,
                         testing::Combine(testing::Values(1, 2, 4), testing::Values(16, 33),
                                          testing::Values("0", "0.5", "-0.5")),
                         [](const auto& info) {
                           std::string alpha = std::get<2>(info.param);
                           std::replace(alpha.begin(), alpha.end(), '.', 'p');
                           std::replace(alpha.begin(), alpha.end(), '-', 'm');
                           return "P" + std::to_string(std::get<0>(info.param)) + "_N" +
                                  std::to_string(std::get<1>(info.param)) + "_alpha" + alpha;
                         });

// Every method fluid-relax-mpi offers (the method table's for any backend) writes what the
// serial app writes with it, on 2 ranks of blocks that divide neither N, α = 0.5.
class FluidRelaxMpiMethodTest : public testing::TestWithParam<std::string> {};

TEST_P(FluidRelaxMpiMethodTest, WritesWhatTheSerialAppWrites) {
  const std::string method = GetParam();
  const fs::path serial = freshFolder("ddb_mpi_serial_", "method_" + method);
  const fs::path mpi = freshFolder("ddb_mpi_", "method_" + method);
  const std::string common = "--n 33 --alpha 0.5 --steps 60 --every 10 --quiet --method " + method;
  const AppResult s = runProgram(FLUID_RELAX_PATH, common + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.output;
  const AppResult m = runMpi(2, common + " --block 5 --out " + mpi.string());
  ASSERT_EQ(m.status, 0) << m.output;
  EXPECT_LT(matrixDistance(readCsv(mpi / "W_final.csv", nullptr),
                           readCsv(serial / "W_final.csv", nullptr)),
            1e-13);
  const bool keeps_casimirs = ddb::findMethod(method)->keeps_casimirs;
  expectSameHistory(mpi, serial, keeps_casimirs);
  expectSameSummary(mpi, serial, 2, 0, keeps_casimirs);
  EXPECT_EQ(readJson(mpi / "summary.json")["method"], method);
  fs::remove_all(serial);
  fs::remove_all(mpi);
}

INSTANTIATE_TEST_SUITE_P(Methods, FluidRelaxMpiMethodTest,
                         testing::ValuesIn(ddb::methodNames(ddb::kBackendMatrixGroups)),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// --newton: the Newton search (OrbitNewton through the distributed backend) on 1, 2 and 4
// ranks of blocks that divide neither N reaches the serial app's steady state. Not its
// iterates to rounding: a search far from a critical point amplifies rounding by 10 to 50
// times an iteration (docs/design/distributed.md, "The Newton search on the ranks"), so the
// iterates agree to 1e-13 for the first three to five only. Here (N = 16, α = −0.5) both runs
// stop at r ≤ 1e-10 after the same iterations, at states within 1e-8 of each other (measured:
// 1e-10 to 3e-10, the critical point's position at that residual), each on W0's orbit.
class FluidRelaxMpiNewtonTest : public testing::TestWithParam<int> {};

TEST_P(FluidRelaxMpiNewtonTest, ReachesTheSerialAppsSteadyState) {
  const int ranks = GetParam();
  const std::string name = "newton_" + std::to_string(ranks);
  const fs::path serial = freshFolder("ddb_mpi_serial_", name);
  const fs::path mpi = freshFolder("ddb_mpi_", name);
  const std::string common =
      "--n 16 --alpha -0.5 --newton --until-steady 1e-10 --steps 400 --every 1 --quiet";
  const AppResult s = runProgram(FLUID_RELAX_PATH, common + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.output;
  const AppResult m = runMpi(ranks, common + " --block 5 --out " + mpi.string());
  ASSERT_EQ(m.status, 0) << m.output;
  const auto a = readJson(mpi / "summary.json"), b = readJson(serial / "summary.json");
  EXPECT_EQ(b["stop"], "steady");
  EXPECT_EQ(a["stop"], "steady");
  EXPECT_EQ(a["steps"], b["steps"]);
  EXPECT_EQ(a["method"], "newton");
  EXPECT_LE(a["residual_final"].get<double>(), 1e-10);
  EXPECT_LT(a["spectrum_drift_max"].get<double>(), 1e-13);
  EXPECT_LT(matrixDistance(readCsv(mpi / "W_final.csv", nullptr),
                           readCsv(serial / "W_final.csv", nullptr)),
            1e-8);
  fs::remove_all(serial);
  fs::remove_all(mpi);
}

INSTANTIATE_TEST_SUITE_P(Ranks, FluidRelaxMpiNewtonTest, testing::Values(1, 2, 4),
                         [](const auto& info) { return "P" + std::to_string(info.param); });

// --grid-rows: the other shapes of 2 and 4 ranks (1×2, 1×4, 4×1) write what the serial app
// writes, as the default shapes do above, and summary.json names the grid.
class FluidRelaxMpiGridTest : public testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(FluidRelaxMpiGridTest, WritesWhatTheSerialAppWrites) {
  const auto [ranks, rows] = GetParam();
  const std::string name = "grid_" + std::to_string(ranks) + "_" + std::to_string(rows);
  const fs::path serial = freshFolder("ddb_mpi_serial_", name);
  const fs::path mpi = freshFolder("ddb_mpi_", name);
  const std::string common = "--n 33 --alpha 0.5 --steps 100 --every 10 --quiet";
  const AppResult s = runProgram(FLUID_RELAX_PATH, common + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.output;
  const AppResult m = runMpi(
      ranks, common + " --block 5 --grid-rows " + std::to_string(rows) + " --out " + mpi.string());
  ASSERT_EQ(m.status, 0) << m.output;
  EXPECT_LT(matrixDistance(readCsv(mpi / "W_final.csv", nullptr),
                           readCsv(serial / "W_final.csv", nullptr)),
            1e-13);
  expectSameHistory(mpi, serial);
  expectSameSummary(mpi, serial, ranks, rows);
  fs::remove_all(serial);
  fs::remove_all(mpi);
}

INSTANTIATE_TEST_SUITE_P(RanksRows, FluidRelaxMpiGridTest,
                         testing::Values(std::tuple{2, 1}, std::tuple{4, 1}, std::tuple{4, 4}),
                         [](const auto& info) {
                           return "P" + std::to_string(std::get<0>(info.param)) + "_rows" +
                                  std::to_string(std::get<1>(info.param));
                         });

// --rotation and --deformation-radius on ranks: the distributed fluid's planetary vorticity and
// shifted Poisson solve give the serial app's files.
TEST(FluidRelaxMpi, RotatingQuasiGeostrophicRunWritesWhatTheSerialAppWrites) {
  const fs::path serial = freshFolder("ddb_mpi_serial_", "rotating");
  const fs::path mpi = freshFolder("ddb_mpi_", "rotating");
  const std::string common =
      "--n 16 --alpha 0.5 --rotation 2 --deformation-radius 0.7 --steps 60 --every 10 --quiet";
  const AppResult s = runProgram(FLUID_RELAX_PATH, common + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.output;
  const AppResult m = runMpi(2, common + " --block 5 --out " + mpi.string());
  ASSERT_EQ(m.status, 0) << m.output;
  EXPECT_LT(matrixDistance(readCsv(mpi / "W_final.csv", nullptr),
                           readCsv(serial / "W_final.csv", nullptr)),
            1e-13);
  expectSameHistory(mpi, serial);
  expectSameSummary(mpi, serial, 2);
  EXPECT_EQ(readJson(mpi / "summary.json")["rotation"], 2.0);
  fs::remove_all(serial);
  fs::remove_all(mpi);
}

// A fixed forcing's file at N: Φ = X3 + a multiple of T_21's matrix (traceless skew-Hermitian).
fs::path writeFixedForcing(const std::string& name, int n) {
  const fs::path phi = freshFolder("ddb_mpi_", name) / "phi.csv";
  fs::create_directories(phi.parent_path());
  Eigen::MatrixXcd matrix = ddb::zeitlinX3(n);
  for (int k = 0; k + 1 < n; ++k) {
    matrix(k, k + 1) += std::complex<double>(0.3, 0.1 * k);
    matrix(k + 1, k) -= std::conj(std::complex<double>(0.3, 0.1 * k));
  }
  writeMatrix(phi, matrix);
  return phi;
}

// Viscosity, hyperviscosity, drag, the stochastic and the fixed forcing on a rotating sphere, on
// 1, 2 and 4 ranks (blocks that do not divide N): the serial app's files. The damping leaves the
// orbit, so the drift is compared as a method's that does not keep the Casimirs.
TEST(FluidRelaxMpi, DampedAndForcedRunWritesWhatTheSerialAppWrites) {
  const int n = 33;
  const fs::path phi = writeFixedForcing("phi_damped", n);
  const fs::path serial = freshFolder("ddb_mpi_serial_", "damped");
  const std::string common =
      "--n 33 --alpha 0.5 --rotation 2 --viscosity 1e-3 "
      "--hyperviscosity-order 2 --drag 0.05 --forcing-band 6:2 "
      "--forcing-rate 1e-3 --forcing-seed 9 --forcing-file " +
      phi.string() + " --steps 40 --every 10 --quiet";
  const AppResult s = runProgram(FLUID_RELAX_PATH, common + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.output;
  for (const auto& [ranks, layout] :
       std::vector<std::pair<int, std::string>>{{1, ""}, {2, " --block 5"}, {4, " --block 4"}}) {
    const fs::path mpi = freshFolder("ddb_mpi_", "damped");
    const AppResult m = runMpi(ranks, common + layout + " --out " + mpi.string());
    ASSERT_EQ(m.status, 0) << m.output;
    EXPECT_LT(matrixDistance(readCsv(mpi / "W_final.csv", nullptr),
                             readCsv(serial / "W_final.csv", nullptr)),
              1e-13)
        << ranks << " ranks";
    expectSameHistory(mpi, serial, false);
    expectSameSummary(mpi, serial, ranks, 0, false);
    EXPECT_EQ(readJson(mpi / "summary.json")["forcing_seed"], 9);
    fs::remove_all(mpi);
  }
  // The viscous flow's implicit step, on 2 ranks.
  const std::string implicit = common + " --viscous-scheme implicit";
  const AppResult si =
      runProgram(FLUID_RELAX_PATH, implicit + " --overwrite --out " + serial.string());
  ASSERT_EQ(si.status, 0) << si.output;
  const fs::path mpi = freshFolder("ddb_mpi_", "damped_implicit");
  const AppResult mi = runMpi(2, implicit + " --block 5 --out " + mpi.string());
  ASSERT_EQ(mi.status, 0) << mi.output;
  EXPECT_LT(matrixDistance(readCsv(mpi / "W_final.csv", nullptr),
                           readCsv(serial / "W_final.csv", nullptr)),
            1e-13);
  EXPECT_EQ(readJson(mpi / "summary.json")["viscous_scheme"], "implicit");
  fs::remove_all(mpi);
  fs::remove_all(serial);
  fs::remove_all(phi.parent_path());
}

TEST(FluidRelaxMpi, StopsWhenSteadyAtTheSerialAppsStep) {
  const fs::path serial = freshFolder("ddb_mpi_serial_", "steady");
  const fs::path mpi = freshFolder("ddb_mpi_", "steady");
  const std::string common = "--n 16 --alpha 0.5 --steps 100000 --until-steady 0.15 --quiet";
  const AppResult s = runProgram(FLUID_RELAX_PATH, common + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.output;
  const AppResult m = runMpi(2, common + " --out " + mpi.string());
  ASSERT_EQ(m.status, 0) << m.output;
  const auto a = readJson(mpi / "summary.json"), b = readJson(serial / "summary.json");
  EXPECT_EQ(b["stop"], "steady");
  EXPECT_EQ(a["stop"], "steady");
  EXPECT_EQ(a["steps"], b["steps"]);
  EXPECT_GT(b["steps"].get<long>(), 10);
  expectSameHistory(mpi, serial);
  fs::remove_all(serial);
  fs::remove_all(mpi);
}

// --adaptive: the energy step control's verdicts, from the energy and dH/dt evaluated
// distributed, are the serial app's: the same step sizes (exactly), the same rejections, a
// state equal to rounding. A first h of 0.5 is rejected and regrown several times (α = 0.5)
// and, with α = −0.5, the run ends at --t-end on a last step shortened onto it.
class FluidRelaxMpiAdaptiveTest : public testing::TestWithParam<std::tuple<int, std::string>> {};

TEST_P(FluidRelaxMpiAdaptiveTest, TakesTheSerialAppsSteps) {
  const auto [ranks, caps] = GetParam();
  const std::string name = "adaptive_" + std::to_string(ranks) + "_" + std::to_string(caps.size());
  const fs::path serial = freshFolder("ddb_mpi_serial_", name);
  const fs::path mpi = freshFolder("ddb_mpi_", name);
  const std::string common = "--n 33 --adaptive --h 0.5 --every 5 --quiet " + caps;
  const AppResult s = runProgram(FLUID_RELAX_PATH, common + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.output;
  const AppResult m = runMpi(ranks, common + " --block 5 --out " + mpi.string());
  ASSERT_EQ(m.status, 0) << m.output;
  const auto summary = readJson(serial / "summary.json");
  EXPECT_GT(summary["steps_rejected"].get<long>(), 3);
  const bool by_time = caps.find("--t-end") != std::string::npos;
  EXPECT_EQ(summary["stop"], by_time ? "time cap" : "step cap");
  EXPECT_LT(matrixDistance(readCsv(mpi / "W_final.csv", nullptr),
                           readCsv(serial / "W_final.csv", nullptr)),
            1e-13);
  expectSameHistory(mpi, serial);
  expectSameSummary(mpi, serial, ranks);
  fs::remove_all(serial);
  fs::remove_all(mpi);
}

INSTANTIATE_TEST_SUITE_P(RanksCaps, FluidRelaxMpiAdaptiveTest,
                         testing::Combine(testing::Values(1, 2, 4),
                                          testing::Values("--alpha 0.5 --steps 40",
                                                          "--alpha -0.5 --t-end 5.3")),
                         [](const auto& info) {
                           return "P" + std::to_string(std::get<0>(info.param)) +
                                  (std::get<1>(info.param).find("--t-end") != std::string::npos
                                       ? "_TimeCap"
                                       : "_StepCap");
                         });

// Bad input: fluid-relax's message from one rank, exit status 2, no output folder; and the
// flags this app does not have.
TEST(FluidRelaxMpi, RefusesBadInputOnEveryRankOnce) {
  const fs::path out = freshFolder("ddb_mpi_", "bad");
  // fluid-relax's own checks are tested on fluid-relax (test_bad_inputs): here one of them
  // with this app's bound on N (the group's, not fluid-relax's 1024), a parse error, a method
  // fluid-relax does not offer (reference), and this app's own.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--n 4097 --steps 10", "--n = 4097: must be in [2, 4096]"},
      {"--steps 10 --bogus", "bogus"},
      {"--n 16 --steps 10 --block 17", "--block"},
      {"--steps 10 --block 2.5", "--block"},
      {"--steps 10 --grid-rows 3", "--grid-rows = 3: must be a divisor of the number of ranks, 2"},
      {"--steps 10 --grid-rows 0", "--grid-rows"},
      {"--steps 10 --grid-rows 1.5", "--grid-rows"},
      {"--steps 10 --grid-rows two", "--grid-rows"},
      {"--steps 10 --method reference", "--method"},
      {"--steps 10 --adaptive --alpha 0", "--adaptive"},
      {"--steps 10 --resume somewhere", "--resume"},
      // fluid-relax's checks of the damping and forcing flags, on every rank.
      {"--steps 10 --viscosity -1e-3", "--viscosity = -1e-3"},
      {"--steps 10 --forcing-band 40:1 --forcing-rate 1e-3", "--forcing-band = 40:1"},
  };
  for (const auto& [arguments, flag] : cases) {
    const AppResult r = runMpi(2, arguments + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output;
    EXPECT_NE(r.error.find(flag), std::string::npos) << arguments << "\n" << r.error;
    // One message, not one per rank.
    EXPECT_EQ(messageCount(r.error), 1u) << arguments << "\n" << r.error;
    EXPECT_FALSE(fs::exists(out)) << arguments;
  }
  // Rows within [1, P] that do not divide P.
  {
    const AppResult r = runMpi(4, "--steps 10 --grid-rows 3 --out " + out.string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.error.find("--grid-rows = 3: must be a divisor of the number of ranks, 4"),
              std::string::npos)
        << r.error;
    EXPECT_EQ(messageCount(r.error), 1u) << r.error;
    EXPECT_FALSE(fs::exists(out));
  }
}

// Every rank's own exit status, not only mpiexec's (which reports the first nonzero one): each
// rank runs under a shell that writes its status to DIR/status.<rank>.
std::vector<int> rankStatuses(int ranks, const std::string& arguments, const fs::path& dir,
                              const RunEnvironment& environment = kMpiEnvironment) {
  fs::create_directories(dir);
  const std::string script =
      "\"$0\" \"$@\"; echo $? > " + dir.string() + "/status.$OMPI_COMM_WORLD_RANK";
  std::vector<std::string> words{"-n",   std::to_string(ranks), "/bin/sh", "-c",
                                 script, FLUID_RELAX_MPI_PATH};
  std::istringstream in(arguments);
  for (std::string word; in >> word;) words.push_back(word);
  runProgram(MPIEXEC_PATH, words, environment);
  std::vector<int> statuses;
  for (int rank = 0; rank < ranks; ++rank) {
    std::ifstream in(dir / ("status." + std::to_string(rank)));
    int status = -1;
    in >> status;
    statuses.push_back(status);
  }
  return statuses;
}

TEST(FluidRelaxMpi, EveryRankExitsWithTheSameStatus) {
  const fs::path dir = freshFolder("ddb_mpi_", "rank_statuses");
  const fs::path out = dir / "out";
  for (const std::string arguments :
       {"--n 8 --steps 10 --grid-rows 3", "--n 8 --steps 10 --grid-rows 0",
        "--n 8 --steps 10 --bogus", "--n 4097 --steps 10", "--n 8 --steps 10 --block 9"}) {
    SCOPED_TRACE(arguments);
    const std::vector<int> statuses =
        rankStatuses(2, arguments + " --quiet --out " + out.string(), dir / "statuses");
    for (std::size_t rank = 0; rank < statuses.size(); ++rank) {
      EXPECT_EQ(statuses[rank], 2) << "rank " << rank;
    }
    EXPECT_FALSE(fs::exists(out));
    fs::remove_all(dir / "statuses");
  }
  // A figure that fails on rank 0 (a matplotlib that cannot be imported) is every rank's
  // exit status 1, not rank 0's alone.
  fs::create_directories(dir / "site" / "matplotlib");
  std::ofstream(dir / "site" / "matplotlib" / "__init__.py")
      << "raise ImportError('this matplotlib is broken on purpose')\n";
  RunEnvironment environment = kMpiEnvironment;
  environment.variables.push_back("PYTHONPATH=" + (dir / "site").string());
  const std::vector<int> statuses = rankStatuses(
      2, "--n 8 --steps 2 --quiet --plot --out " + out.string(), dir / "statuses", environment);
  for (std::size_t rank = 0; rank < statuses.size(); ++rank) {
    EXPECT_EQ(statuses[rank], 1) << "rank " << rank;
  }
  EXPECT_EQ(readJson(out / "summary.json")["status"], "figures_failed");
}

// ---- Checkpoints, --resume and --h5 ----

// Rows every 3 steps and a checkpoint every 7, so that a run of 20 ends on a held-back row
// after periodic checkpoints; α = 0.5, so that the Legendre solver's warm start (the
// predictor's remembered corrections) decides its iterates.
const std::string kResumable = "--alpha 0.5 --every 3 --checkpoint-every 7 --h5 --quiet";

/// fluid.hdf5's per-frame datasets, numbers and matrices.
struct Frames {
  std::vector<long long> step;
  std::vector<double> time, qtime, energy, enstrophy, commutator, drift, state;
  std::vector<std::complex<double>> mat;
};

Frames readFrames(const fs::path& dir) {
  const fs::path file = dir / "fluid.hdf5";
  hsize_t rows = 0;
  Frames f;
  f.step = readAll<long long>(file, "step", H5T_NATIVE_LLONG, &rows);
  f.time = readAll<double>(file, "time", H5T_NATIVE_DOUBLE, &rows);
  f.qtime = readAll<double>(file, "qtime", H5T_NATIVE_DOUBLE, &rows);
  f.energy = readAll<double>(file, "energy_euler", H5T_NATIVE_DOUBLE, &rows);
  f.enstrophy = readAll<double>(file, "enstrophy", H5T_NATIVE_DOUBLE, &rows);
  f.commutator = readAll<double>(file, "commutator_norm", H5T_NATIVE_DOUBLE, &rows);
  f.drift = readAll<double>(file, "spectrum_drift", H5T_NATIVE_DOUBLE, &rows);
  f.state = readAll<double>(file, "state", H5T_NATIVE_DOUBLE, &rows);
  const hid_t complex = complexType();
  f.mat = readAll<std::complex<double>>(file, "mat", complex, &rows);
  H5Tclose(complex);
  return f;
}

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expectSameBits(const Frames& a, const Frames& b) {
  EXPECT_TRUE(sameBits(a.step, b.step));
  EXPECT_TRUE(sameBits(a.time, b.time));
  EXPECT_TRUE(sameBits(a.qtime, b.qtime));
  EXPECT_TRUE(sameBits(a.energy, b.energy));
  EXPECT_TRUE(sameBits(a.enstrophy, b.enstrophy));
  EXPECT_TRUE(sameBits(a.commutator, b.commutator));
  EXPECT_TRUE(sameBits(a.drift, b.drift));
  EXPECT_TRUE(sameBits(a.state, b.state));
  EXPECT_TRUE(sameBits(a.mat, b.mat));
}

// ‖a − b‖/‖b‖ over a whole dataset.
template <class T>
double datasetDistance(const std::vector<T>& a, const std::vector<T>& b) {
  double difference = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    difference += std::norm(a[i] - b[i]);
    norm += std::norm(b[i]);
  }
  return std::sqrt(difference / norm);
}

// The tolerances of the comparisons above: the matrices (W as mat, ω as state) as W_final,
// history's numbers as history.csv's, times and steps exact.
void expectSameFrames(const fs::path& found, const fs::path& serial) {
  const Frames a = readFrames(found), b = readFrames(serial);
  ASSERT_EQ(a.step, b.step);
  ASSERT_GT(b.step.size(), 2u);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.qtime, b.qtime);
  for (std::size_t f = 0; f < b.step.size(); ++f) {
    EXPECT_LT(relative(a.energy[f], b.energy[f]), 1e-11) << "frame " << f;
    EXPECT_LT(relative(a.enstrophy[f], b.enstrophy[f]), 1e-11) << "frame " << f;
    EXPECT_LT(relative(a.commutator[f], b.commutator[f]), 1e-11) << "frame " << f;
    EXPECT_LT(a.drift[f], 1e-13) << "frame " << f;
  }
  ASSERT_EQ(a.mat.size(), b.mat.size());
  ASSERT_EQ(a.state.size(), b.state.size());
  EXPECT_LT(datasetDistance(a.mat, b.mat), 1e-13);
  EXPECT_LT(datasetDistance(a.state, b.state), 1e-12);
}

nlohmann::ordered_json summaryWithoutRuntime(const fs::path& out) {
  nlohmann::ordered_json summary = readJson(out / "summary.json");
  summary.erase("runtime_s");
  return summary;
}

// A run of 40 steps against one of 20 resumed to 40, on `ranks` ranks with the flags
// `layout` (--block, or none) and `control` (--adaptive, or none) and of size `n`: every
// file the same bytes.
void expectResumedRunToTheBit(int ranks, int n, const std::string& layout,
                              const std::string& control = "") {
  const fs::path whole = freshFolder("ddb_mpi_", "whole");
  const fs::path resumed = freshFolder("ddb_mpi_", "resumed");
  const std::string run = kResumable + " --n " + std::to_string(n) + layout + control;
  const AppResult a = runMpi(ranks, run + " --steps 40 --out " + whole.string());
  ASSERT_EQ(a.status, 0) << a.output;
  const AppResult b = runMpi(ranks, run + " --steps 20 --out " + resumed.string());
  ASSERT_EQ(b.status, 0) << b.output;
  const AppResult c =
      runMpi(ranks, "--quiet --steps 40" + layout + " --resume " + resumed.string());
  ASSERT_EQ(c.status, 0) << c.output;
  for (const char* file :
       {"history.csv", "W_final.csv", "omega_initial.csv", "omega_final.csv", "checkpoint.ddb"}) {
    EXPECT_TRUE(readFile(resumed / file) == readFile(whole / file)) << file;
  }
  EXPECT_EQ(summaryWithoutRuntime(resumed), summaryWithoutRuntime(whole));
  expectSameBits(readFrames(resumed), readFrames(whole));
  EXPECT_EQ(readFrames(whole).step.size(), 15u);  // rows 0, 3, ..., 39 and 40
  fs::remove_all(whole);
  fs::remove_all(resumed);
}

TEST(FluidRelaxMpiCheckpoint, ResumedRunContinuesTheUninterruptedOneToTheBit) {
  expectResumedRunToTheBit(2, 16, "");
}

// On a 2×2 grid with blocks of 5 that do not divide N = 33 (partial blocks in both
// directions): the state and the warm start's corrections, scattered from rank 0's record
// on resume, must land on the blocks they came from.
TEST(FluidRelaxMpiCheckpoint, ResumedRunOnAGridOfBlocksContinuesToTheBit) {
  expectResumedRunToTheBit(4, 33, " --block 5");
}

// With --adaptive the checkpoint carries the step control (h, its floor, the good steps in a
// row) and the state's dH/dt is evaluated again on resume: the resumed run chooses the
// uninterrupted run's steps.
TEST(FluidRelaxMpiCheckpoint, ResumedAdaptiveRunContinuesToTheBit) {
  expectResumedRunToTheBit(2, 16, "", " --adaptive --h 0.5");
}

// A damped and forced run (the random stream's position and Φ in the record) on a 2×2 grid of
// blocks that do not divide N resumes to the bit.
TEST(FluidRelaxMpiCheckpoint, ResumedDampedAndForcedRunContinuesToTheBit) {
  const fs::path phi = writeFixedForcing("phi_resumed", 33);
  expectResumedRunToTheBit(4, 33, " --block 5",
                           " --rotation 1 --viscosity 1e-3 --drag 0.05 --forcing-band 5:2 "
                           "--forcing-rate 1e-3 --forcing-file " +
                               phi.string());
  fs::remove_all(phi.parent_path());
}

// A Newton search with α > 0 (its trust radius is in the record; its direction, to lower the
// energy, comes from W₀'s energy rate, W₀ read from the checkpoint) resumes to the bit.
TEST(FluidRelaxMpiCheckpoint, ResumedNewtonSearchContinuesToTheBit) {
  expectResumedRunToTheBit(2, 16, "", " --newton --until-steady 1e-12");
}

// A checkpoint of either app resumed by the other: the runs end where the uninterrupted
// serial run does, to the rounding the MPI runs differ by (pzgemm's sums).
TEST(FluidRelaxMpiCheckpoint, EitherAppResumesTheOthersCheckpoint) {
  const fs::path serial = freshFolder("ddb_mpi_serial_", "cross");
  const fs::path mpi_then_serial = freshFolder("ddb_mpi_", "mpi_then_serial");
  const fs::path serial_then_mpi = freshFolder("ddb_mpi_", "serial_then_mpi");
  const std::string common = kResumable + " --n 33";
  AppResult r = runProgram(FLUID_RELAX_PATH, common + " --steps 40 --out " + serial.string());
  ASSERT_EQ(r.status, 0) << r.output;
  r = runMpi(2, common + " --block 5 --steps 20 --out " + mpi_then_serial.string());
  ASSERT_EQ(r.status, 0) << r.output;
  r = runProgram(FLUID_RELAX_PATH, "--quiet --steps 40 --resume " + mpi_then_serial.string());
  ASSERT_EQ(r.status, 0) << r.output;
  r = runProgram(FLUID_RELAX_PATH, common + " --steps 20 --out " + serial_then_mpi.string());
  ASSERT_EQ(r.status, 0) << r.output;
  r = runMpi(2, "--quiet --block 5 --steps 40 --resume " + serial_then_mpi.string());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const fs::path& resumed : {mpi_then_serial, serial_then_mpi}) {
    SCOPED_TRACE(resumed.string());
    EXPECT_LT(matrixDistance(readCsv(resumed / "W_final.csv", nullptr),
                             readCsv(serial / "W_final.csv", nullptr)),
              1e-12);
    expectSameHistory(resumed, serial);
    expectSameFrames(resumed, serial);
    EXPECT_EQ(readJson(resumed / "summary.json")["steps"], 40);
  }
  fs::remove_all(serial);
  fs::remove_all(mpi_then_serial);
  fs::remove_all(serial_then_mpi);
}

TEST(FluidRelaxMpiCheckpoint, H5IsTheSerialAppsFile) {
  const fs::path serial = freshFolder("ddb_mpi_serial_", "h5");
  const fs::path mpi = freshFolder("ddb_mpi_", "h5");
  const std::string common = "--n 33 --alpha -0.5 --steps 30 --every 4 --h5 --quiet";
  const AppResult s = runProgram(FLUID_RELAX_PATH, common + " --out " + serial.string());
  ASSERT_EQ(s.status, 0) << s.output;
  const AppResult m = runMpi(4, common + " --block 5 --out " + mpi.string());
  ASSERT_EQ(m.status, 0) << m.output;
  expectSameFrames(mpi, serial);
  fs::remove_all(serial);
  fs::remove_all(mpi);
}

// Every file of a folder with its bytes: what a refused resume must leave as it was.
std::vector<std::pair<std::string, std::string>> folderBytes(const fs::path& dir) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    files.emplace_back(entry.path().filename().string(), readFile(entry.path()));
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(FluidRelaxMpiCheckpoint, RefusesBadResumesOnEveryRankOnce) {
  const fs::path done = freshFolder("ddb_mpi_", "done");
  const fs::path corrupt = freshFolder("ddb_mpi_", "corrupt");
  AppResult r = runMpi(2, kResumable + " --n 16 --steps 10 --out " + done.string());
  ASSERT_EQ(r.status, 0) << r.output;
  fs::copy(done, corrupt);
  {
    std::string bytes = readFile(corrupt / "checkpoint.ddb");
    bytes[bytes.size() / 2] ^= 1;
    std::ofstream(corrupt / "checkpoint.ddb", std::ios::binary) << bytes;
  }
  const fs::path missing = freshFolder("ddb_mpi_", "missing");
  const std::vector<std::tuple<std::string, fs::path, std::string>> cases = {
      {"--resume " + missing.string(), missing, "no checkpoint to resume from"},
      {"--steps 20 --resume " + corrupt.string(), corrupt, "is corrupt (checksum mismatch)"},
      {"--resume " + done.string(), done, "the run has taken 10 steps, its cap 10"},
      {"--steps 20 --grid-rows 3 --resume " + done.string(), done, "--grid-rows = 3"},
  };
  for (const auto& [arguments, folder, message] : cases) {
    const bool existed = fs::exists(folder);
    const auto before = existed ? folderBytes(folder) : decltype(folderBytes(folder)){};
    const AppResult bad = runMpi(2, arguments);
    EXPECT_EQ(bad.status, 2) << arguments << "\n" << bad.output;
    EXPECT_NE(bad.error.find(message), std::string::npos) << arguments << "\n" << bad.error;
    EXPECT_EQ(messageCount(bad.error), 1u) << arguments << "\n" << bad.error;
    EXPECT_EQ(fs::exists(folder), existed) << arguments;
    if (existed) {
      EXPECT_EQ(folderBytes(folder), before) << arguments;
    }
  }
  // --grid-rows may be given anew with --resume, as --block may
  // (docs/reference/command-lines-and-files.md).
  const AppResult regrid = runMpi(2, "--quiet --steps 12 --grid-rows 1 --resume " + done.string());
  EXPECT_EQ(regrid.status, 0) << regrid.output;
  for (const fs::path& folder : {done, corrupt}) fs::remove_all(folder);
}

TEST(FluidRelaxMpiCheckpoint, AFolderAnotherProcessWritesIsRefusedOnEveryRank) {
  // A serial run that is going (a checkpoint every step) holds the folder's lock
  // (docs/reference/command-lines-and-files.md, "Run folders"): fluid-relax-mpi's rank 0 is
  // refused, once, and every rank exits 2 without touching the folder.
  const fs::path going = freshFolder("ddb_mpi_", "going");
  std::vector<std::string> words{
      FLUID_RELAX_PATH, "--quiet", "--n",   "24",          "--checkpoint-every", "1",
      "--steps",        "1000000", "--out", going.string()};
  const pid_t child = startUntilCheckpoint(words, going);
  for (const std::string& arguments :
       {"--quiet --steps 2000000 --resume " + going.string(),
        "--quiet --n 16 --steps 10 --overwrite --out " + going.string()}) {
    const AppResult r = runMpi(2, arguments);
    EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output;
    EXPECT_NE(r.error.find("the folder is in use by process " + std::to_string(child)),
              std::string::npos)
        << arguments << "\n"
        << r.error;
    EXPECT_EQ(messageCount(r.error), 1u) << arguments << "\n" << r.error;
  }
  ::kill(child, SIGKILL);
  EXPECT_EQ(waitForExit(child), -SIGKILL);
  fs::remove_all(going);
}

// Starts `mpiexec -n 2 fluid-relax-mpi arguments` (output discarded), waits for its first
// checkpoint, sends SIGTERM to one rank (as a batch system signals the tasks) and returns
// mpiexec's exit status.
int startAndTerminateOneRank(const std::string& arguments) {
  std::vector<std::string> words{MPIEXEC_PATH, "-n", "2", FLUID_RELAX_MPI_PATH};
  std::stringstream ss(arguments);
  for (std::string word; ss >> word;) words.push_back(word);
  const pid_t child =
      startUntilCheckpoint(words, words[words.size() - 1], kMpiEnvironment.variables);
  // mpiexec's children are the ranks.
  std::ifstream children("/proc/" + std::to_string(child) + "/task/" + std::to_string(child) +
                         "/children");
  pid_t rank = 0;
  children >> rank;
  if (rank > 0) ::kill(rank, SIGTERM);
  return waitForExit(child);
}

// A run stopped by SIGTERM under mpiexec (at whatever step the signal finds it) writes its
// outputs and a checkpoint and exits 143; resumed, it ends as the uninterrupted run, to the
// bit.
TEST(FluidRelaxMpiCheckpoint, SigtermLeavesACheckpointThatResumesToTheBit) {
  const fs::path whole = freshFolder("ddb_mpi_", "sigterm_whole");
  const fs::path stopped = freshFolder("ddb_mpi_", "sigterm_stopped");
  const std::string run = "--n 16 --alpha 0.5 --every 3 --checkpoint-every 5 --steps 600";
  EXPECT_EQ(startAndTerminateOneRank(run + " --out " + stopped.string()), 143);
  const auto summary = readJson(stopped / "summary.json");
  EXPECT_EQ(summary["stop"], "interrupted");
  EXPECT_LT(summary["steps"].get<long>(), 600);
  const AppResult resumed = runMpi(2, "--quiet --resume " + stopped.string());
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  const AppResult a = runMpi(2, run + " --quiet --out " + whole.string());
  ASSERT_EQ(a.status, 0) << a.output;
  for (const char* file : {"history.csv", "W_final.csv", "omega_final.csv", "checkpoint.ddb"}) {
    EXPECT_TRUE(readFile(stopped / file) == readFile(whole / file)) << file;
  }
  fs::remove_all(whole);
  fs::remove_all(stopped);
}

}  // namespace
}  // namespace ddb::test
