// mhd-relax end to end at N = 8 and 12 (docs/reference/command-lines-and-files.md, "mhd-relax"):
// the files against the contract (columns, rows, JSON keys), the final fields against the library
// called directly, every Casimir tr Θᵏ and tr(WΘᵏ) of the group (an O(N⁴) set the app does not
// evaluate) kept to rounding, the total energy monotone for α > 0, a magnetic equilibrium reached
// under --until-steady, and with Θ₀ = 0 fluid-relax's run to the bit. Bad inputs are rows of
// docs/reference/bad-inputs.md (test_bad_inputs.cc).
#include <ddb/groups/dual_number_sun.h>
#include <ddb/integrators/drivers/integrate.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <gmock/gmock.h>
#include <signal.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "app_test_support.h"

namespace mhd_relax_tests {

using namespace ddb::test;
using Matrix = Eigen::MatrixXcd;
using State = ddb::DualMatrix<Matrix>;

AppResult run(const std::string& arguments) { return runProgram(MHD_RELAX_PATH, arguments); }

/// The app's generated fields (--init random --seed, --theta-lmax, --theta-seed, --theta-scale),
/// from the library's generators as docs/reference/command-lines-and-files.md defines them.
State initialState(long n, std::uint64_t seed, long lmax, std::uint64_t theta_seed, double scale) {
  const Matrix W0 = ddb::randomVorticity(n, seed);
  const Matrix shape = ddb::lowModeVorticity(n, lmax, theta_seed);
  return ddb::zeitlinMhdState(W0, shape * (scale * W0.norm() / shape.norm()));
}

TEST(MhdRelax, WritesContractFilesMatchingTheLibraryAndKeepsEveryCasimir) {
  // An exponential method too: its spectral calculus is the dual numbers' own
  // (core/dual_eigenbasis.h).
  for (const auto& [n, method_name] :
       {std::pair{8L, "ddb-cay"}, std::pair{12L, "ddb-cay"}, std::pair{8L, "sddb-exp"}}) {
    const fs::path out = freshFolder("mhd_relax_test_", "contract");
    const double alpha = 0.03, h = 0.01;
    const long steps = 60;
    const std::string args = "--quiet --n " + std::to_string(n) + " --method " + method_name +
                             " --alpha 0.03 --h 0.01 --steps 60 --every 7 --seed 3 "
                             "--theta-seed 5 --theta-lmax 3 --theta-scale 0.2 --out " +
                             out.string();
    const AppResult r = run(args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.output;
    for (const char* name :
         {"history.csv", "fluid.hdf5", "summary.json", "W_final.csv", "theta_final.csv"}) {
      EXPECT_TRUE(fs::exists(out / name)) << name;
    }
    EXPECT_FALSE(fs::exists(out / "history.csv.partial"));
    EXPECT_FALSE(fs::exists(out / "fluid.hdf5.partial"));

    std::string header;
    const auto rows = readCsv(out / "history.csv", &header);
    EXPECT_EQ(header,
              "t,h,kinetic_energy,magnetic_energy,energy,cross_helicity,residual,"
              "equilibrium_residual,invariant_drift");
    ASSERT_EQ(rows.size(), 10u);  // k = 0, 7, ..., 56 and the last, 60
    EXPECT_NEAR(rows.back()[0], steps * h, 1e-12);
    for (size_t i = 0; i < rows.size(); ++i) {
      ASSERT_EQ(rows[i].size(), 9u);
      for (double v : rows[i]) EXPECT_TRUE(std::isfinite(v));
      EXPECT_EQ(rows[i][4], rows[i][2] + rows[i][3]);
      EXPECT_LE(rows[i][8], 1e-13) << "invariant drift, row " << i;
      // The cross helicity is the ε-part's k = 1 Casimir.
      EXPECT_NEAR(rows[i][5], rows[0][5], 1e-13 * std::abs(rows[0][5]));
      if (i > 0) {
        EXPECT_LT(rows[i][4], rows[i - 1][4]) << "the total energy falls, row " << i;
      }
    }

    // The final fields against the library's own integrate() of the same state.
    const State mu0 = initialState(n, 3, 3, 5, 0.2);
    const auto system = ddb::makeZeitlinMhd(n, alpha);
    const auto method = ddb::makeMethod<ddb::DualNumberSUN>(method_name, system);
    State expected;
    ddb::integrate(*method, mu0, 0.0, h, steps,
                   [&](long, double, const State& mu) { expected = mu; });
    const Matrix W = readMatrix(out / "W_final.csv");
    const Matrix Theta = readMatrix(out / "theta_final.csv");
    ASSERT_EQ(W.rows(), n);
    EXPECT_LT((W - expected.eps).norm(), 1e-13 * expected.eps.norm());
    EXPECT_LT((Theta - expected.real).norm(), 1e-13 * expected.real.norm());
    // Every Casimir of SU(N) ⋉ su(N)* (tr Hᵏ, k = 2..N, and tr(HᵏK), k = 0..N−1), which the
    // app's O(N³) drift column does not evaluate.
    const Eigen::VectorXd c0 = ddb::DualNumberSUN::casimirs(mu0);
    const Eigen::VectorXd c1 = ddb::DualNumberSUN::casimirs(ddb::zeitlinMhdState(W, Theta));
    for (Eigen::Index i = 0; i < c0.size(); ++i) {
      EXPECT_NEAR(c1(i), c0(i), 1e-12 * std::max(1.0, std::abs(c0(i)))) << "Casimir " << i;
    }

    const auto summary = readJson(out / "summary.json");
    EXPECT_EQ(summary["status"], "ok");
    EXPECT_EQ(summary["method"], method_name);
    EXPECT_EQ(summary["n"], n);
    EXPECT_EQ(summary["steps"], steps);
    EXPECT_EQ(summary["stop"], "step cap");
    EXPECT_EQ(summary["theta_init"], "low-modes");
    EXPECT_EQ(summary["energy_rises"], 0);
    EXPECT_EQ(summary["energy_initial"].get<double>(), rows.front()[4]);
    EXPECT_EQ(summary["energy_final"].get<double>(), rows.back()[4]);
    EXPECT_LE(summary["invariant_drift_max"].get<double>(), 1e-13);
    EXPECT_GE(summary["iterations_max"].get<double>(), 1.0);
    fs::remove_all(out);
  }
}

TEST(MhdRelax, UntilSteadyStopsAtAMagneticEquilibrium) {
  const fs::path out = freshFolder("mhd_relax_test_", "steady");
  const AppResult r =
      run("--quiet --n 8 --alpha 0.5 --h 0.05 --adaptive --t-end 1e4 "
          "--until-steady 1e-6 --every 1000 --out " +
          out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["stop"], "steady");
  EXPECT_LE(summary["residual_final"].get<double>(), 1e-6);
  // At the equilibrium [P, Θ] = 0 and [P, W] + [B, Θ] = 0, computed here from the final fields
  // with the library's Laplacian.
  const Matrix W = readMatrix(out / "W_final.csv");
  const Matrix Theta = readMatrix(out / "theta_final.csv");
  const ddb::HoppeYauLaplacian laplacian(8);
  Matrix P(8, 8), B(8, 8);
  laplacian.solve(W, P);
  laplacian.apply(Theta, B);
  const double scale = (P.norm() + B.norm()) * (W.norm() + Theta.norm());
  EXPECT_LT((P * Theta - Theta * P).norm(), 1e-5 * scale);
  EXPECT_LT((P * W - W * P + B * Theta - Theta * B).norm(), 1e-5 * scale);
  EXPECT_LT(summary["energy_final"].get<double>(), summary["energy_initial"].get<double>());
  fs::remove_all(out);
}

TEST(MhdRelax, WithoutMagneticFieldItIsFluidRelaxToTheBit) {
  const fs::path mhd = freshFolder("mhd_relax_test_", "fluid");
  const fs::path fluid = freshFolder("mhd_relax_test_", "fluid_reference");
  const std::string common = "--quiet --n 10 --alpha 0.2 --h 0.02 --steps 30 --seed 4 ";
  const AppResult a = run(common + "--theta-scale 0 --out " + mhd.string());
  ASSERT_EQ(a.status, 0) << a.output;
  const AppResult b = runProgram(FLUID_RELAX_PATH, common + "--out " + fluid.string());
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(readFile(mhd / "W_final.csv"), readFile(fluid / "W_final.csv"));
  EXPECT_EQ(readMatrix(mhd / "theta_final.csv").norm(), 0.0);
  fs::remove_all(mhd);
  fs::remove_all(fluid);
}

/// Runs mhd-relax in the background until its first checkpoint appears, then sends `signal`;
/// returns the exit status (−signal if it killed it).
int startAndSignal(const std::string& arguments, const fs::path& out, int signal) {
  std::vector<std::string> words{MHD_RELAX_PATH};
  std::stringstream ss(arguments + " --out " + out.string());
  for (std::string word; ss >> word;) words.push_back(word);
  const pid_t child = startUntilCheckpoint(words, out);
  ::kill(child, signal);
  return waitForExit(child);
}

/// The files of a finished run that must equal an uninterrupted run's byte for byte (summary.json
/// has the runtime, fluid.hdf5 its time of creation: its datasets are compared in
/// tests/python/test_mhd_h5.py).
void expectSameFiles(const fs::path& a, const fs::path& b) {
  for (const char* name : {"history.csv", "W_final.csv", "theta_final.csv"}) {
    EXPECT_EQ(readFile(a / name), readFile(b / name)) << name;
  }
  EXPECT_FALSE(fs::exists(b / "history.csv.partial"));
  EXPECT_FALSE(fs::exists(b / "fluid.hdf5.partial"));
}

TEST(MhdRelax, AKilledOrInterruptedRunResumesToTheByte) {
  const std::string run_flags = "--quiet --n 16 --steps 3000 --every 7 --checkpoint-every 50 ";
  const fs::path whole = freshFolder("mhd_relax_test_", "whole");
  ASSERT_EQ(run(run_flags + "--out " + whole.string()).status, 0);
  for (const int signal : {SIGKILL, SIGINT}) {
    const fs::path out = freshFolder("mhd_relax_test_", "stopped");
    const int status = startAndSignal(run_flags, out, signal);
    if (signal == SIGKILL) {
      ASSERT_EQ(status, -SIGKILL);
      ASSERT_FALSE(fs::exists(out / "summary.json")) << "the run finished before the kill";
    } else {
      ASSERT_EQ(status, 130);
      EXPECT_EQ(readJson(out / "summary.json")["status"], "interrupted");
    }
    const AppResult resumed = run("--quiet --resume " + out.string());
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    expectSameFiles(whole, out);
    EXPECT_EQ(readJson(out / "summary.json")["steps"], 3000);
    fs::remove_all(out);
  }
  // A finished run continued to a later cap: the longer run's files.
  const fs::path longer = freshFolder("mhd_relax_test_", "longer");
  ASSERT_EQ(run("--quiet --n 16 --steps 3100 --every 7 --out " + longer.string()).status, 0);
  const AppResult more = run("--quiet --resume " + whole.string() + " --steps 3100");
  ASSERT_EQ(more.status, 0) << more.output;
  expectSameFiles(longer, whole);
  fs::remove_all(whole);
  fs::remove_all(longer);
}

// The linearly implicit method (its dissipative factor a Newton step on the orbit, which keeps no
// state between steps) continued past a finished run's cap: the longer run's files.
TEST(MhdRelax, ALinearlyImplicitRunContinuedIsTheLongerRun) {
  const std::string flags = "--quiet --n 16 --method ddb-cay-implicit --h 0.2 --every 3 ";
  const fs::path longer = freshFolder("mhd_relax_test_", "implicit-longer");
  ASSERT_EQ(run(flags + "--steps 40 --out " + longer.string()).status, 0);
  const fs::path out = freshFolder("mhd_relax_test_", "implicit");
  ASSERT_EQ(run(flags + "--steps 20 --out " + out.string()).status, 0);
  const AppResult more = run("--quiet --resume " + out.string() + " --steps 40");
  ASSERT_EQ(more.status, 0) << more.output;
  expectSameFiles(longer, out);
  EXPECT_EQ(readJson(out / "summary.json")["method"], "ddb-cay-implicit");
  fs::remove_all(longer);
  fs::remove_all(out);
}

TEST(MhdRelax, AResumeRefusesWhatWouldChangeTheRun) {
  const fs::path out = freshFolder("mhd_relax_test_", "refused");
  ASSERT_EQ(run("--quiet --n 8 --steps 10 --out " + out.string()).status, 0);
  const std::string before = readFile(out / "checkpoint.ddb");
  for (const std::string extra : {"--alpha 0.5", "--n 12", "--method rk4", "--theta-scale 0"}) {
    const AppResult r = run("--quiet --resume " + out.string() + " --steps 20 " + extra);
    EXPECT_EQ(r.status, 2) << extra;
    EXPECT_THAT(r.error, ::testing::HasSubstr("does not apply to --resume")) << extra;
  }
  const AppResult reached = run("--quiet --resume " + out.string() + " --steps 10");
  EXPECT_EQ(reached.status, 2);
  EXPECT_THAT(reached.error, ::testing::HasSubstr("give a larger --steps"));
  // An altered history is another run's.
  std::ofstream(out / "history.csv", std::ios::app) << "1,2,3\n";
  std::string history = readFile(out / "history.csv");
  history[40] = history[40] == '1' ? '2' : '1';
  std::ofstream(out / "history.csv", std::ios::trunc) << history;
  const AppResult altered = run("--quiet --resume " + out.string() + " --steps 20");
  EXPECT_EQ(altered.status, 2);
  EXPECT_THAT(altered.error, ::testing::HasSubstr("is not the history its checkpoint continues"));
  EXPECT_EQ(readFile(out / "checkpoint.ddb"), before) << "a refused resume changed nothing";
  fs::remove_all(out);
}

}  // namespace mhd_relax_tests
