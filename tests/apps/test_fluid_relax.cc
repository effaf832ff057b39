// fluid-relax end to end at N = 8 and 16 (docs/reference/command-lines-and-files.md,
// "fluid-relax"): the files against the contract (columns, rows, JSON keys, finite values),
// W_final.csv against the library called directly, the spectrum kept to round-off, the energy
// monotone in the direction of alpha's sign, the --init-file round trip, and every bad input (exit
// status 2, a message naming the flag, nothing written).
#include <ddb/core/openblas_kernels.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_spectra.h>
#include <gmock/gmock.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app_test_support.h"
#include "cpu_flags.h"

namespace fluid_relax_tests {

using namespace ddb::test;
using Matrix = Eigen::MatrixXcd;

AppResult run(const std::string& arguments) { return runProgram(FLUID_RELAX_PATH, arguments); }

fs::path freshFolder(const std::string& name) {
  return ddb::test::freshFolder("fluid_relax_test_", name);
}

/// summary.json's number `key`; NaN if it is missing or not a number (null).
double jsonNumber(const nlohmann::ordered_json& json, const std::string& key) {
  const auto at = json.find(key);
  return at != json.end() && at->is_number() ? at->get<double>() : NAN;
}

/// The library called directly: `steps` steps of `method` with h from W0.
Matrix libraryFinal(const Matrix& W0, double alpha, const std::string& method, double h,
                    long steps) {
  auto fluid = ddb::makeZeitlinFluid(W0.rows(), alpha);
  auto integrator = ddb::makeMethod<ddb::SUN>(method, fluid);
  Matrix last;
  ddb::integrate(*integrator, W0, 0.0, h, steps, [&](long, double, const Matrix& W) { last = W; });
  return last;
}

TEST(FluidRelax, WritesContractFilesMatchingTheLibrary) {
  for (int n : {8, 16}) {
    for (double alpha : {0.5, -0.5}) {
      const std::string method = alpha > 0 ? "sddb-cay" : "ddb-cay";
      const fs::path out = freshFolder("contract");
      const long steps = 40, every = n == 8 ? 3 : 1;
      const double h = 0.05;
      const std::string args = "--quiet --n " + std::to_string(n) + " --alpha " +
                               std::to_string(alpha) + " --h 0.05 --steps 40 --seed 3 --method " +
                               method + " --every " + std::to_string(every) + " --out " +
                               out.string();
      const AppResult r = run(args);
      ASSERT_EQ(r.status, 0) << args << "\n" << r.output;

      std::string header;
      const auto rows = readCsv(out / "history.csv", &header);
      EXPECT_EQ(header, "t,energy,enstrophy,commutator_norm,spectrum_drift,h,residual,gamma");
      // k = 0, 3, ..., 39 and the last, 40; or every k.
      ASSERT_EQ(rows.size(), every == 3 ? 15u : 41u);
      EXPECT_NEAR(rows.back()[0], steps * h, 1e-12);
      for (size_t i = 0; i < rows.size(); ++i) {
        ASSERT_EQ(rows[i].size(), 8u);
        EXPECT_EQ(rows[i][5], i == 0 ? 0.0 : h) << "the step that reached row " << i;
        for (double v : rows[i]) EXPECT_TRUE(std::isfinite(v));
        EXPECT_LE(rows[i][4], 1e-12) << "spectrum drift, N = " << n;
        EXPECT_NEAR(rows[i][2], 0.5, 1e-12) << "enstrophy of ||W||_F = sqrt(N)";
        if (i > 0) {
          // dE/dt = −α‖[P, W]‖²/(ħN) (docs/reference/conventions.md §2): E falls for α > 0, rises
          // for α < 0.
          EXPECT_LT(alpha * (rows[i][1] - rows[i - 1][1]), 0.0) << "N = " << n << " row " << i;
        }
      }

      const Matrix W0 = ddb::randomVorticity(n, 3);
      const Matrix expected = libraryFinal(W0, alpha, method, h, steps);
      const Matrix W = readMatrix(out / "W_final.csv");
      ASSERT_EQ(W.rows(), n);
      EXPECT_LT((W - expected).cwiseAbs().maxCoeff(), 1e-13) << "N = " << n;
      // gamma (from the matrix, O(N²)) against the coefficients of every degree.
      const ddb::SphericalHarmonicBasis basis{ddb::HoppeYauLaplacian(n)};
      EXPECT_NEAR(rows.front()[7], ddb::zeitlinGamma(basis.coefficients(W0)), 1e-13);
      EXPECT_NEAR(rows.back()[7], ddb::zeitlinGamma(basis.coefficients(W)), 1e-13);

      auto summary = readJson(out / "summary.json");
      for (const std::string key : {"n", "alpha", "h", "steps", "energy_initial", "energy_final",
                                    "enstrophy", "spectrum_drift_max", "commutator_final",
                                    "runtime_s", "iterations_mean", "iterations_max", "t_end"}) {
        EXPECT_TRUE(std::isfinite(jsonNumber(summary, key))) << key;
      }
      EXPECT_EQ(jsonNumber(summary, "n"), n);
      EXPECT_EQ(jsonNumber(summary, "steps"), steps);
      EXPECT_EQ(summary["stop"], "step cap");
      EXPECT_EQ(summary["steady"], false);
      EXPECT_EQ(jsonNumber(summary, "steps_rejected"), 0);
      EXPECT_EQ(jsonNumber(summary, "h"), h);
      EXPECT_EQ(jsonNumber(summary, "seed"), 3);
      EXPECT_EQ(summary["method"], method);
      EXPECT_EQ(summary["init"], "random");
      EXPECT_LE(jsonNumber(summary, "spectrum_drift_max"), 1e-12);
      EXPECT_GE(jsonNumber(summary, "iterations_max"), jsonNumber(summary, "iterations_mean"));
      EXPECT_GE(jsonNumber(summary, "iterations_mean"), 1.0);

      // ω_lm of W_final: N² rows, and W_final rebuilt from them (docs/reference/conventions.md §2).
      const auto omega = readCsv(out / "omega_final.csv", &header);
      EXPECT_EQ(header, "l,m,omega");
      ASSERT_EQ(omega.size(), static_cast<size_t>(n * n));
      Eigen::VectorXd coefficients(n * n);
      for (size_t i = 0; i < omega.size(); ++i) {
        coefficients(ddb::SphericalHarmonicBasis::index(long(omega[i][0]), long(omega[i][1]))) =
            omega[i][2];
      }
      EXPECT_LT((basis.matrix(coefficients) - W).norm(), 1e-13 * W.norm());
      EXPECT_TRUE(fs::exists(out / "omega_initial.csv"));
    }
  }
}

// iterations_mean and iterations_max are those of every method that solves, as the library's
// methods count them (OneStepMethod::lastStepIterations, checked against the solvers' own
// counts in test_method_table.cc): the exp methods and the compositions too, where they were
// 0; null for rk4 and a Newton search, which solve no equation of a step.
TEST(FluidRelax, IterationsPerStepAreThoseOfEveryMethodThatSolves) {
  const int n = 8;
  const long steps = 6;
  const double h = 0.05, alpha = 0.5;
  const Matrix W0 = ddb::randomVorticity(n, 3);
  for (const std::string method : {"ddb-exp", "ddb-exp-exact", "sddb-exp", "ddb4-cay", "ddb6-exp",
                                   "ddb-cay-implicit", "lobatto3c", "rk4"}) {
    const fs::path out = freshFolder("iterations");
    const std::string args = "--quiet --n 8 --alpha 0.5 --h 0.05 --steps 6 --seed 3 --method " +
                             method + " --out " + out.string();
    const AppResult r = run(args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.output;
    const auto summary = readJson(out / "summary.json");

    auto integrator = ddb::makeMethod<ddb::SUN>(method, ddb::makeZeitlinFluid(n, alpha));
    long total = 0, most = 0;
    ddb::integrate(*integrator, W0, 0.0, h, steps, [&](long k, double, const Matrix&) {
      if (k == 0) return;
      total += integrator->lastStepIterations();
      most = std::max(most, integrator->lastStepIterations());
    });
    if (!integrator->solvesEquations()) {
      EXPECT_TRUE(summary["iterations_mean"].is_null()) << method;
      EXPECT_TRUE(summary["iterations_max"].is_null()) << method;
      continue;
    }
    EXPECT_GE(most, 1) << method;
    EXPECT_EQ(jsonNumber(summary, "iterations_mean"), static_cast<double>(total) / steps) << method;
    EXPECT_EQ(jsonNumber(summary, "iterations_max"), most) << method;
  }
  const fs::path out = freshFolder("iterations-newton");
  const AppResult r =
      run("--quiet --n 8 --alpha 0.5 --seed 3 --newton --until-steady 1e-8 "
          "--steps 50 --out " +
          out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto summary = readJson(out / "summary.json");
  EXPECT_TRUE(summary["iterations_mean"].is_null());
  EXPECT_TRUE(summary["iterations_max"].is_null());
}

TEST(FluidRelax, UntilSteadyStopsAtTheResidualWithAdaptiveOrFixedSteps) {
  // N = 4 relaxes to r = 1e-9 with ddb-exp-exact in 6477 steps of h = 0.1, or about a
  // thousand adaptive ones; r of W_final.csv from its own stream matrix, the residual column
  // of the history, the stop reason of summary.json.
  for (const std::string mode : {"", " --adaptive"}) {
    SCOPED_TRACE(mode);
    const fs::path out = freshFolder("steady");
    const std::string args =
        "--quiet --n 4 --alpha 0.5 --h 0.1 --steps 200000 --seed 1 "
        "--method ddb-exp-exact --until-steady 1e-9 --every 100 --out " +
        out.string() + mode;
    const AppResult r = run(args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.output;
    const auto summary = readJson(out / "summary.json");
    EXPECT_EQ(summary["stop"], "steady");
    EXPECT_EQ(summary["steady"], true);
    const Matrix W = readMatrix(out / "W_final.csv");
    const ddb::ZeitlinHamiltonian hamiltonian(4);
    const Matrix P = hamiltonian.streamMatrix(W);
    const double residual = (P * W - W * P).norm() / (P.norm() * W.norm());
    EXPECT_LE(residual, 1e-9);
    EXPECT_NEAR(jsonNumber(summary, "residual_final"), residual, 1e-15);
    EXPECT_LE(jsonNumber(summary, "spectrum_drift_max"), 1e-12);
    EXPECT_EQ(jsonNumber(summary, "energy_rises"), 0);
    std::string header;
    const auto rows = readCsv(out / "history.csv", &header);
    EXPECT_NEAR(rows.back()[6], residual, 1e-15);
    EXPECT_GT(rows[rows.size() - 2][6], 1e-9) << "not steady before the last state";
    if (mode.empty()) {
      EXPECT_EQ(jsonNumber(summary, "steps_rejected"), 0);
      EXPECT_EQ(jsonNumber(summary, "h_final"), 0.1);
    } else {
      EXPECT_GE(jsonNumber(summary, "steps_rejected"), 0);
      EXPECT_EQ(summary["adaptive_tol"], 0.5);
    }
  }
}

TEST(FluidRelax, AdaptiveTimeCapStopsAtTEnd) {
  const fs::path out = freshFolder("timecap");
  const std::string args =
      "--quiet --n 4 --alpha 50 --h 0.5 --t-end 3 --seed 1 --adaptive "
      "--until-steady 1e-12 --out " +
      out.string();
  const AppResult r = run(args);
  ASSERT_EQ(r.status, 0) << args << "\n" << r.output;
  const auto summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["stop"], "time cap");
  EXPECT_NEAR(jsonNumber(summary, "t_end"), 3.0, 1e-12);
  EXPECT_GT(jsonNumber(summary, "steps_rejected"), 0) << "alpha = 50 at h = 0.5";
  EXPECT_EQ(jsonNumber(summary, "energy_rises"), 0);
}

TEST(FluidRelax, AdaptiveTakesAnyFirstStepAndGrowsIt) {
  // --h is only the first step with --adaptive: 1e-300 runs (doubling every 4 good steps,
  // about 4000 steps) to the time cap, where it was refused as "more than 1e9 steps".
  const fs::path out = freshFolder("tiny_first_step");
  const AppResult r = run("--quiet --n 8 --adaptive --h 1e-300 --t-end 1 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["stop"], "time cap");
  EXPECT_NEAR(jsonNumber(summary, "t_end"), 1.0, 1e-12);
  EXPECT_EQ(jsonNumber(summary, "h"), 1e-300);
  EXPECT_GT(jsonNumber(summary, "h_final"), 1e-3);
}

TEST(FluidRelax, DefaultStepIsTwoHundredthsOfHbarOverTheStreamNorm) {
  const fs::path out = freshFolder("default_h");
  ASSERT_EQ(run("--quiet --n 8 --init l1 --seed 2 --t-end 0.5 --out " + out.string()).status, 0);
  auto summary = readJson(out / "summary.json");
  const Matrix W0 = ddb::l1Vorticity(8, 2);
  const ddb::ZeitlinHamiltonian hamiltonian(8);
  const double norm = Eigen::JacobiSVD<Matrix>(hamiltonian.streamMatrix(W0)).singularValues()(0);
  const double h0 = 0.02 * hamiltonian.hbar() / norm;
  // --t-end with the default h: the fewest equal steps no longer than h0 that end at T.
  const double steps = std::ceil(0.5 / h0);
  EXPECT_EQ(jsonNumber(summary, "steps"), steps);
  EXPECT_NEAR(jsonNumber(summary, "h"), 0.5 / steps, 1e-15);
  EXPECT_NEAR(jsonNumber(summary, "t_end"), 0.5, 1e-12);
  EXPECT_EQ(summary["h_source"], "default");
  std::string header;
  EXPECT_EQ(readCsv(out / "history.csv", &header).size(), steps + 1);
}

// With a large α the default h is the stiffness bound h|α|‖W₀‖₂²/ħ = 4
// (docs/design/architecture.md, "Large N: the step's stability bound"), and the energy falls at
// every step; 2.5 times that h (stiffness 10) is past the bound and the energy rises.
TEST(FluidRelax, DefaultStepKeepsTheDissipationWithinItsStabilityBound) {
  const fs::path out = freshFolder("default_h_stiff");
  ASSERT_EQ(run("--quiet --n 32 --alpha 50 --steps 100 --out " + out.string()).status, 0);
  const auto summary = readJson(out / "summary.json");
  const Matrix W0 = ddb::randomVorticity(32, 1);
  const ddb::ZeitlinHamiltonian hamiltonian(32);
  const auto largestSingularValue = [](const Matrix& A) {
    return Eigen::JacobiSVD<Matrix>(A).singularValues()(0);
  };
  const double w = largestSingularValue(W0);
  const double stiffness_h = 4.0 * hamiltonian.hbar() / (50.0 * w * w);
  ASSERT_LT(stiffness_h,
            0.02 * hamiltonian.hbar() / largestSingularValue(hamiltonian.streamMatrix(W0)));
  EXPECT_NEAR(jsonNumber(summary, "h"), stiffness_h, 1e-14 * stiffness_h);
  EXPECT_EQ(jsonNumber(summary, "energy_rises"), 0);
  EXPECT_LT(jsonNumber(summary, "energy_final"), jsonNumber(summary, "energy_initial"));

  const fs::path past = freshFolder("default_h_past");
  std::ostringstream past_h;
  past_h.precision(17);
  past_h << 2.5 * stiffness_h;
  ASSERT_EQ(
      run("--quiet --n 32 --alpha 50 --steps 100 --h " + past_h.str() + " --out " + past.string())
          .status,
      0);
  EXPECT_GT(jsonNumber(readJson(past / "summary.json"), "energy_rises"), 0);
}

TEST(FluidRelax, InitFileRoundTripContinuesTheLongerRun) {
  const fs::path first = freshFolder("first"), second = freshFolder("second"),
                 whole = freshFolder("whole");
  const std::string common = "--quiet --alpha 0.5 --h 0.04 --method ddb-cay ";
  ASSERT_EQ(run(common + "--n 16 --seed 5 --steps 30 --out " + first.string()).status, 0);
  ASSERT_EQ(run(common + "--n 16 --seed 5 --steps 50 --out " + whole.string()).status, 0);
  const AppResult r = run(common + "--init-file " + (first / "W_final.csv").string() +
                          " --steps 20 --out " + second.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const Matrix continued = readMatrix(second / "W_final.csv");
  const Matrix longer = readMatrix(whole / "W_final.csv");
  EXPECT_LT((continued - longer).cwiseAbs().maxCoeff(), 1e-13);
  // The continuation's history is the longer run's from step 30 on (its t restarts at 0).
  std::string header;
  const auto rows = readCsv(second / "history.csv", &header);
  const auto whole_rows = readCsv(whole / "history.csv", &header);
  ASSERT_EQ(rows.size(), 21u);
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_NEAR(rows[i][1], whole_rows[30 + i][1], 1e-13);
    EXPECT_NEAR(rows[i][3], whole_rows[30 + i][3], 1e-12 * whole_rows[30][3]);
  }
  auto summary = readJson(second / "summary.json");
  EXPECT_EQ(summary["init"], "file");
  EXPECT_EQ(summary["init_file"], (first / "W_final.csv").string());
  EXPECT_TRUE(summary["seed"].is_null());
  EXPECT_EQ(jsonNumber(summary, "n"), 16);
}

// --rotation and --deformation-radius: a Rossby–Haurwitz wave given as --init-file (the relative
// vorticity W0 = T_32 + 0.6 T_3,-2) ends in W_final.csv rotated by c t, c = 2Ω/(l(l + 1) + κ²),
// the closed form (docs/reference/conventions.md §2); the energy is ‖W0‖²/(2N(l(l + 1) + κ²)).
TEST(FluidRelax, RotationAndDeformationRadiusCarryARossbyHaurwitzWave) {
  const Eigen::Index n = 8;
  const ddb::SphericalHarmonicBasis basis{ddb::HoppeYauLaplacian(n)};
  const Matrix W0 = basis.element(3, 2) + 0.6 * basis.element(3, -2);
  const fs::path files = freshFolder("rossby_haurwitz_input"), out = freshFolder("rossby_haurwitz");
  fs::create_directories(files);
  writeMatrix(files / "W0.csv", W0);
  const AppResult r =
      run("--quiet --alpha 0 --rotation 1.5 --deformation-radius 0.5 --method rk4 "
          "--h 0.01 --steps 300 --h5 --init-file " +
          (files / "W0.csv").string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const double c = 2.0 * 1.5 / (12.0 + 4.0), t = 3.0;
  Eigen::VectorXcd u(n);
  for (Eigen::Index j = 0; j < n; ++j) u(j) = std::polar(1.0, double(j) * c * t);
  const Matrix expected = u.asDiagonal() * W0 * u.conjugate().asDiagonal();
  const Matrix W = readMatrix(out / "W_final.csv");
  EXPECT_LT((W - expected).norm(), 1e-9 * W0.norm());
  const auto summary = readJson(out / "summary.json");
  EXPECT_EQ(jsonNumber(summary, "rotation"), 1.5);
  EXPECT_EQ(jsonNumber(summary, "deformation_radius"), 0.5);
  const double energy = W0.squaredNorm() / (2.0 * double(n) * 16.0);
  EXPECT_NEAR(jsonNumber(summary, "energy_initial"), energy, 1e-12 * energy);
  // Without the flags the summary says so: no rotation, no deformation radius.
  const fs::path resting = freshFolder("resting");
  ASSERT_EQ(run("--quiet --n 4 --steps 2 --out " + resting.string()).status, 0);
  const auto plain = readJson(resting / "summary.json");
  EXPECT_EQ(jsonNumber(plain, "rotation"), 0.0);
  EXPECT_TRUE(plain["deformation_radius"].is_null());
  EXPECT_EQ(jsonNumber(plain, "viscosity"), 0.0);
  EXPECT_EQ(jsonNumber(plain, "drag"), 0.0);
  EXPECT_TRUE(plain["forcing_band"].is_null());
  EXPECT_EQ(jsonNumber(plain, "forcing_rate"), 0.0);
  EXPECT_TRUE(plain["forcing_seed"].is_null());
}

// --viscosity, --hyperviscosity-order and --drag: a field of one degree l is steady for the Euler
// part ([P, W] = 0, so the double bracket does nothing either), and the damping multiplies it by
// exp(−(ν (l(l + 1))^p + γ) t), the closed form (docs/reference/conventions.md §2). rk4's stages
// vanish there, so the run is that closed form to rounding (a DDB step moves such a field by its
// local error: ddb-cay by about 3e-6 per step of h = 0.05 at N = 8). On a rotating
// sphere the same field is a Rossby–Haurwitz wave, rotated by c t and damped alike.
TEST(FluidRelax, ViscosityAndDragDampAFieldOfOneDegreeByTheClosedForm) {
  const Eigen::Index n = 8;
  const ddb::SphericalHarmonicBasis basis{ddb::HoppeYauLaplacian(n)};
  const fs::path files = freshFolder("damped_input");
  fs::create_directories(files);
  const Matrix steady = basis.element(2, 1) + 0.5 * basis.element(2, -2);
  writeMatrix(files / "steady.csv", steady);
  const fs::path out = freshFolder("damped");
  const AppResult r =
      run("--quiet --alpha 0.5 --viscosity 0.01 --hyperviscosity-order 2 "
          "--drag 0.05 --h 0.05 --steps 40 --method rk4 --init-file " +
          (files / "steady.csv").string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const double rate = 0.01 * 36.0 + 0.05;  // l = 2: (l(l + 1))² = 36
  EXPECT_LT((readMatrix(out / "W_final.csv") - std::exp(-rate * 2.0) * steady).norm(),
            1e-12 * steady.norm());
  const auto summary = readJson(out / "summary.json");
  EXPECT_EQ(jsonNumber(summary, "viscosity"), 0.01);
  EXPECT_EQ(jsonNumber(summary, "hyperviscosity_order"), 2);
  EXPECT_EQ(jsonNumber(summary, "drag"), 0.05);

  const Matrix wave = basis.element(3, 2) + 0.6 * basis.element(3, -2);
  writeMatrix(files / "wave.csv", wave);
  const fs::path rotating = freshFolder("damped_wave");
  const AppResult w =
      run("--quiet --alpha 0 --rotation 1.5 --viscosity 0.02 --method rk4 "
          "--h 0.01 --steps 300 --init-file " +
          (files / "wave.csv").string() + " --out " + rotating.string());
  ASSERT_EQ(w.status, 0) << w.output;
  const double c = 2.0 * 1.5 / 12.0, t = 3.0;
  Eigen::VectorXcd u(n);
  for (Eigen::Index j = 0; j < n; ++j) u(j) = std::polar(1.0, double(j) * c * t);
  const Matrix expected =
      std::exp(-0.02 * 12.0 * t) * u.asDiagonal() * wave * u.adjoint().asDiagonal();
  EXPECT_LT((readMatrix(rotating / "W_final.csv") - expected).norm(), 1e-9 * wave.norm());
}

// --forcing-band, --forcing-rate and --forcing-seed (systems/zeitlin_forcing.h, whose mean
// injection rate the unit tests hold to ε): summary.json records them, the same seed gives the
// same bits, another seed another flow, and energy rises are not counted (a forced run's energy
// rises by design).
TEST(FluidRelax, AForcedRunIsItsSeedsAndRecordsItsForcing) {
  const std::string forced =
      "--quiet --n 12 --alpha 0.5 --steps 60 --forcing-band 5:2 --forcing-rate 0.01 ";
  const fs::path a = freshFolder("forced_a"), b = freshFolder("forced_b"),
                 c = freshFolder("forced_c");
  ASSERT_EQ(run(forced + "--forcing-seed 3 --out " + a.string()).status, 0);
  ASSERT_EQ(run(forced + "--forcing-seed 3 --out " + b.string()).status, 0);
  ASSERT_EQ(run(forced + "--forcing-seed 4 --out " + c.string()).status, 0);
  EXPECT_EQ(readFile(a / "W_final.csv"), readFile(b / "W_final.csv"));
  EXPECT_GT((readMatrix(a / "W_final.csv") - readMatrix(c / "W_final.csv")).norm(), 1e-6);
  const auto summary = readJson(a / "summary.json");
  EXPECT_EQ(summary["forcing_band"].get<std::string>(), "5:2");
  EXPECT_EQ(jsonNumber(summary, "forcing_rate"), 0.01);
  EXPECT_EQ(jsonNumber(summary, "forcing_seed"), 3);
  EXPECT_FALSE(summary.contains("energy_rises")) << "not counted";
}

// A fixed forcing (--forcing-file) of a zonal flow on a rotating sphere: zonal flows are steady
// ([P, W] = 0, and the double bracket vanishes with it), so W(t) = W0 + t Φ to rounding.
TEST(FluidRelax, AFixedForcingOfAZonalFlowAddsTimesPhi) {
  const fs::path files = freshFolder("phi"), out = freshFolder("fixed_forced");
  fs::create_directories(files);
  const int n = 8;
  const Matrix phi = 0.3 * ddb::zeitlinX3(n);
  const Matrix W0 = ddb::zonalVorticity(n, 2);
  writeMatrix(files / "phi.csv", phi);
  writeMatrix(files / "w0.csv", W0);
  const AppResult r =
      run("--quiet --alpha 0.5 --rotation 2 --method sddb-cay --h 0.02 --steps 50 "
          "--init-file " +
          (files / "w0.csv").string() + " --forcing-file " + (files / "phi.csv").string() +
          " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const Matrix expected = W0 + 1.0 * phi;  // t = 50 · 0.02
  EXPECT_LT((readMatrix(out / "W_final.csv") - expected).norm(), 1e-12 * expected.norm());
  const auto summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["forcing_file"].get<std::string>(), (files / "phi.csv").string());
  EXPECT_FALSE(summary.contains("energy_rises")) << "not counted";
}

TEST(FluidRelax, FailedSolveKeepsTheHistoryPrefixAndExitsOne) {
  // At h = 3 (h||P||_2/hbar about 15) the Legendre solve of step 1 does not converge. (At
  // h = 2.2 it failed too until ξ was evaluated on su(N) and projected onto it; now it
  // converges: docs/design/architecture.md, "Systems on matrix groups".)
  const fs::path out = freshFolder("failure");
  const AppResult r = run("--quiet --n 8 --h 3 --steps 50 --out " + out.string());
  EXPECT_EQ(r.status, 1) << r.output;
  for (const std::string text : {"step 1 ", "t = 3", "h = 3", "residual"}) {
    EXPECT_THAT(r.output, ::testing::HasSubstr(text)) << r.output;
  }
  std::string header;
  const auto rows = readCsv(out / "history.csv", &header);
  ASSERT_EQ(rows.size(), 2u);  // t = 0 and t = 2.2, the states before the failing step
  for (const auto& row : rows)
    for (double v : row) EXPECT_TRUE(std::isfinite(v));
  auto summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["status"], "FAILED");
  EXPECT_EQ(jsonNumber(summary, "steps"), 1);
  EXPECT_FALSE(fs::exists(out / "W_final.csv"));
  EXPECT_FALSE(fs::exists(out / "omega_final.csv"));
}

TEST(FluidRelax, BadInputExitsTwoNamingTheFlagAndWritesNothing) {
  const fs::path files = freshFolder("bad_files");
  fs::create_directories(files);
  const int n = 4;
  Matrix W = ddb::randomVorticity(n, 1);
  writeMatrix(files / "good.csv", W);
  {
    std::ofstream(files / "short_row.csv") << "0,1,2\n0,1,2,3,4,5,6,7\n";
    std::ofstream(files / "rows.csv") << "0,0,0,0\n";  // one row: N = 1
    std::ofstream(files / "word.csv") << readFile(files / "good.csv").replace(0, 1, "x");
    Matrix hermitian = W;
    hermitian(0, 1) = -hermitian(0, 1);  // W[0,1] no longer −conj(W[1,0])
    writeMatrix(files / "not_skew.csv", hermitian);
    Matrix traced = W;
    traced(0, 0) += std::complex<double>(0, 1e-6);
    writeMatrix(files / "trace.csv", traced);
  }
  const std::string file = " --steps 2 --init-file " + files.string();
  const std::vector<std::pair<std::string, std::string>> bad{
      {"--n 1 --steps 2", "--n"},
      {"--n 1025 --steps 2", "--n"},
      {"--n -3 --steps 2", "--n"},
      {"--h 0 --steps 2", "--h"},
      {"--h -0.1 --steps 2", "--h"},
      {"--h nan --steps 2", "--h"},
      {"--h inf --steps 2", "--h"},
      {"--alpha nan --steps 2", "--alpha"},
      {"--alpha inf --steps 2", "--alpha"},
      {"--rotation nan --steps 2", "--rotation"},
      {"--rotation inf --steps 2", "--rotation"},
      {"--rotation fast --steps 2", "--rotation"},
      {"--deformation-radius 0 --steps 2", "--deformation-radius"},
      {"--deformation-radius -1 --steps 2", "--deformation-radius"},
      {"--deformation-radius inf --steps 2", "--deformation-radius"},
      {"--viscosity -1e-3 --steps 2", "--viscosity"},
      {"--viscosity nan --steps 2", "--viscosity"},
      {"--viscosity inf --steps 2", "--viscosity"},
      {"--drag -0.1 --steps 2", "--drag"},
      {"--drag inf --steps 2", "--drag"},
      {"--hyperviscosity-order 0 --steps 2", "--hyperviscosity-order"},
      {"--hyperviscosity-order 17 --steps 2", "--hyperviscosity-order"},
      {"--hyperviscosity-order 1.5 --steps 2", "--hyperviscosity-order"},
      {"--viscosity 1e-3 --newton --until-steady 1e-6 --steps 2", "--viscosity"},
      {"--drag 0.1 --adaptive --steps 2", "--drag"},
      {"--steps 0", "--steps"},
      {"--steps -1", "--steps"},
      {"--steps 2 --t-end 1", "--steps"},
      {"--alpha 0.5", "--steps"},
      {"--t-end 0", "--t-end"},
      {"--t-end nan", "--t-end"},
      {"--init vortex --steps 2", "--init"},
      {"--method sddb-paper-cay --steps 2", "--method"},
      {"--every 0 --steps 2", "--every"},
      {"--steps 2 --init-file " + (files / "missing.csv").string(), "--init-file"},
      {"--steps 2 --init-file " + files.string(), "--init-file"},  // a folder
      {file + "/short_row.csv", "--init-file"},
      {file + "/rows.csv", "--init-file"},
      {file + "/word.csv", "--init-file"},
      {file + "/not_skew.csv", "--init-file"},
      {file + "/trace.csv", "--init-file"},
      {file + "/good.csv --n 5", "--n"},
      {file + "/good.csv --init l1", "--init"},
      {file + "/good.csv --seed 3", "--seed"},
      // A fixed forcing's file, read as --init-file's.
      {file + "/good.csv --forcing-file " + (files / "not_skew.csv").string(), "--forcing-file"},
      {file + "/good.csv --forcing-file " + (files / "trace.csv").string(), "--forcing-file"},
      {file + "/good.csv --forcing-file " + (files / "word.csv").string(), "--forcing-file"},
  };
  for (const auto& [arguments, flag] : bad) {
    const fs::path out = freshFolder("bad");
    const AppResult r = run(arguments + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output;
    EXPECT_THAT(r.output, ::testing::StartsWith("fluid-relax: ")) << arguments;
    EXPECT_THAT(r.output, ::testing::HasSubstr(flag)) << arguments << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(out)) << arguments;
  }
  // The good file is accepted: the cases above fail for the reason they name.
  const fs::path out = freshFolder("good_file");
  EXPECT_EQ(run("--quiet" + file + "/good.csv --n 4 --out " + out.string()).status, 0);
}

// --device: the CPU run's summary says "cpu"; --device cuda, where this build has the CUDA
// backend and a GPU is present, follows the CPU run of a damped and forced fluid (W_final.csv to
// 1e-12 of its largest entry, the same history rows) and names the device in its summary; elsewhere
// it is refused, exit status 2 with one line naming --device and why, nothing written
// (docs/guide/gpu.md).
TEST(FluidRelax, DeviceCudaFollowsTheCpuRunOrIsRefusedSayingWhy) {
  const fs::path cpu = freshFolder("device_cpu"), gpu = freshFolder("device_cuda");
  // Damped and forced on a rotating sphere, so that the flows run on the device's states too.
  const std::string physics =
      "--rotation 1 --viscosity 1e-3 --drag 0.01 --forcing-band 4:1 --forcing-rate 1e-3 ";
  const std::string common = "--quiet --n 12 --steps 20 --method sddb-cay " + physics;
  const AppResult a = run(common + "--out " + cpu.string());
  ASSERT_EQ(a.status, 0) << a.output;
  EXPECT_EQ(readJson(cpu / "summary.json")["device"], "cpu");
  const AppResult b = run(common + "--device cuda --out " + gpu.string());
  if (b.status == 2) {
    EXPECT_THAT(b.error, ::testing::StartsWith("fluid-relax: --device = cuda: ")) << b.error;
    EXPECT_EQ(std::count(b.error.begin(), b.error.end(), '\n'), 1) << b.error;
    EXPECT_FALSE(fs::exists(gpu));
    return;
  }
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_THAT(readJson(gpu / "summary.json")["device"].get<std::string>(),
              ::testing::StartsWith("cuda: "));
  const Matrix on_cpu = readMatrix(cpu / "W_final.csv"), on_gpu = readMatrix(gpu / "W_final.csv");
  EXPECT_LE((on_gpu - on_cpu).cwiseAbs().maxCoeff(), 1e-12 * on_cpu.cwiseAbs().maxCoeff());
  EXPECT_EQ(readCsv(gpu / "history.csv", nullptr).size(),
            readCsv(cpu / "history.csv", nullptr).size());
  // Each run resumed on the other device: the CPU's checkpoint on the GPU and back, 10 steps
  // more, both within 1e-12 of a CPU run of 30 steps.
  const fs::path whole = freshFolder("device_whole");
  ASSERT_EQ(
      run("--quiet --n 12 --steps 30 --method sddb-cay " + physics + "--out " + whole.string())
          .status,
      0);
  const Matrix expected = readMatrix(whole / "W_final.csv");
  for (const auto& [folder, device] : {std::pair{cpu, "cuda"}, {gpu, "cpu"}}) {
    const AppResult r =
        run("--quiet --resume " + folder.string() + " --steps 30 --device " + device);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_LE((readMatrix(folder / "W_final.csv") - expected).cwiseAbs().maxCoeff(),
              1e-12 * expected.cwiseAbs().maxCoeff())
        << "resumed on " << device;
  }
  for (const fs::path& folder : {cpu, gpu, whole}) fs::remove_all(folder);
}

// A run on the CPU loads none of CUDA's libraries, whose start alone costs about 0.4 s and 260 MB
// (apps/fluid_relax/device.h): the dynamic loader's list of the files it loads (LD_DEBUG=files)
// names OpenBLAS and no cuBLAS, cuSOLVER or CUDA runtime. Where the CUDA backend is built,
// --device cuda loads them (to ask for a GPU), so the list is one that would name them.
TEST(FluidRelax, ARunOnTheCpuLoadsNoCudaLibrary) {
  const fs::path out = freshFolder("no_cuda");
  RunEnvironment loader;
  loader.variables = {"LD_DEBUG=files"};
  const AppResult r =
      runProgram(FLUID_RELAX_PATH, "--quiet --n 4 --steps 2 --out " + out.string(), loader);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.error, ::testing::HasSubstr("file=libopenblas"));
  for (const char* library : {"file=libcublas", "file=libcusolver", "file=libcudart"}) {
    EXPECT_THAT(r.error, ::testing::Not(::testing::HasSubstr(library)));
  }
#ifdef DDB_FLUID_RELAX_HAS_CUDA_MODULE
  const AppResult on_gpu =
      runProgram(FLUID_RELAX_PATH,
                 "--quiet --n 4 --steps 2 --device cuda --out " + out.string() + "_gpu", loader);
  EXPECT_THAT(on_gpu.error, ::testing::HasSubstr("file=libcublas"));
  fs::remove_all(out.string() + "_gpu");
#endif
  fs::remove_all(out);
}

// Under OpenBLAS's generic Prescott kernels on a CPU with AVX2 (what Debian 12's OpenBLAS picks on
// CPUs newer than itself), a run says so once, naming OPENBLAS_CORETYPE; under Haswell's kernels
// it says nothing; a refusal stays one line (docs/guide/performance.md, "OpenBLAS's kernels").
TEST(FluidRelax, SaysOnceWhenOpenBlasRunsKernelsBelowTheCpus) {
  if (ddb::openblasConfig().find("DYNAMIC_ARCH") == std::string::npos) {
    GTEST_SKIP() << "not an OpenBLAS that picks its kernels at load time (DYNAMIC_ARCH)";
  }
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2: no kernels better than Prescott's to name";
  const auto count = [](const std::string& text, const std::string& what) {
    long n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  const std::string wide =
      cpuHasAvx512() ? "OPENBLAS_CORETYPE=SkylakeX" : "OPENBLAS_CORETYPE=Haswell";
  for (const std::string core : {"Prescott", "Haswell"}) {
    const fs::path out = freshFolder("kernels_" + core);
    const RunEnvironment environment{{"OPENBLAS_CORETYPE=" + core}};
    const AppResult r =
        runProgram(FLUID_RELAX_PATH, "--n 8 --steps 2 --out " + out.string(), environment);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(count(r.error, "OPENBLAS_CORETYPE="), core == "Prescott" ? 1 : 0) << r.error;
    if (core == "Prescott") {
      EXPECT_THAT(r.error, ::testing::HasSubstr(wide)) << r.error;
    }
    const AppResult bad = runProgram(
        FLUID_RELAX_PATH, "--n 8 --steps -1 --out " + out.string() + "_bad", environment);
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(count(bad.error, "\n"), 1) << bad.error;
    fs::remove_all(out);
  }
}

TEST(FluidRelax, HelpListsMethodsInitsAndDefaults) {
  const AppResult r = run("--help");
  EXPECT_EQ(r.status, 0);
  for (const std::string text :
       {"--n INT=32", "--alpha TEXT=0.5", "--method TEXT=ddb-cay", "--init TEXT=random",
        "--seed UINT=1", "--out TEXT=results-fluid", "--every INT=1", "N <= 1024",
        "--device TEXT=cpu", "0.02 hbar/||P0||_2", "\n  ddb-cay ", "\n  sddb-cay ", "\n  rk4 ",
        "\n  random ", "\n  l1 ", "\n  zonal "}) {
    EXPECT_THAT(r.output, ::testing::HasSubstr(text)) << r.output;
  }
}

}  // namespace fluid_relax_tests
