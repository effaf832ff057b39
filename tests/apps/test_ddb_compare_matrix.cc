// ddb-compare on matrix groups (docs/reference/command-lines-and-files.md, "ddb-compare"), end to
// end at small N: the Manakov body on SO(N) and Zeitlin's fluid on SU(N). Every method of the
// method table for matrix groups runs; its final state in summary.json equals, bit for bit, the
// library's makeMethod<SON/SUN> run directly here on the same problem; err_final and the
// spectrum drift are recomputed here with Eigen's Hermitian eigensolver; bad inputs exit
// 2 and write nothing.
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/one_step_method.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gmock/gmock.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <complex>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "app_test_support.h"

namespace ddb_compare_matrix_tests {

using namespace ddb::test;
using Json = nlohmann::ordered_json;

AppResult run(const std::string& arguments) { return runProgram(DDB_COMPARE_PATH, arguments); }

fs::path freshFolder(const std::string& name) {
  return ddb::test::freshFolder("ddb_compare_matrix_test_", name);
}

/// The matrix of summary.json's {"re": rows, "im": rows}.
Eigen::MatrixXcd matrixOf(const Json& state) {
  const Json& re = state.at("re");
  const Json& im = state.at("im");
  const std::size_t n = re.size();
  Eigen::MatrixXcd m(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(re[i].size(), n);
    for (std::size_t j = 0; j < n; ++j) {
      m(Eigen::Index(i), Eigen::Index(j)) = {re[i][j].get<double>(), im[i][j].get<double>()};
    }
  }
  return m;
}

/// The spectrum of a skew-Hermitian (or real skew) matrix: the eigenvalues of −iM, ascending.
Eigen::VectorXd spectrum(const Eigen::MatrixXcd& m) {
  const Eigen::MatrixXcd hermitian = std::complex<double>(0.0, -1.0) * m;
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(hermitian, Eigen::EigenvaluesOnly)
      .eigenvalues();
}

/// The library run directly: the final state, and ‖λ(t) − λ(0)‖/‖λ(0)‖ at it and at most.
template <class G>
struct DirectRun {
  typename G::template Dual<double> last;
  double drift_last = 0.0, drift_max = 0.0;
};

template <class G>
DirectRun<G> runDirectly(const std::string& method,
                         std::shared_ptr<const ddb::LiePoissonSystem<G>> system,
                         const typename G::template Dual<double>& mu0, double h, long steps) {
  auto integrator = ddb::makeMethod<G>(method, system);
  DirectRun<G> result{mu0};
  const Eigen::VectorXd l0 = spectrum(mu0.template cast<std::complex<double>>());
  ddb::integrate(*integrator, mu0, 0.0, h, steps,
                 [&](long, double, const typename G::template Dual<double>& mu) {
                   result.last = mu;
                   const Eigen::VectorXd l = spectrum(mu.template cast<std::complex<double>>());
                   result.drift_last = (l - l0).norm() / l0.norm();
                   result.drift_max = std::max(result.drift_max, result.drift_last);
                 });
  return result;
}

/// Checks every method of summary.json against the library run directly (bit for bit),
/// its err_final against the directly computed reference, its drift against Eigen's.
template <class G>
void expectMethodsMatchTheLibrary(const fs::path& out,
                                  std::shared_ptr<const ddb::LiePoissonSystem<G>> system,
                                  const typename G::template Dual<double>& mu0, double h,
                                  long steps) {
  const Json summary = readJson(out / "summary.json");
  // Every method of the table for matrix groups that applies ran.
  std::vector<std::string> expected;
  for (const auto& name : ddb::methodNames(ddb::kMatrixGroups)) {
    if (ddb::methodApplies(name, *system)) expected.push_back(name);
  }
  ASSERT_FALSE(expected.empty());
  ASSERT_EQ(summary["methods"].size(), expected.size());
  const auto reference =
      runDirectly<G>("reference", system, mu0, summary["t_end"].get<double>(), 1);
  for (const auto& name : expected) {
    SCOPED_TRACE(name);
    const Json& entry = summary["methods"][name];
    ASSERT_EQ(entry["status"], "ok");
    EXPECT_EQ(entry["steps"], steps);
    const Eigen::MatrixXcd app_final = matrixOf(entry["final"]);
    const DirectRun<G> direct_run = runDirectly<G>(name, system, mu0, h, steps);
    const auto& last = direct_run.last;
    const Eigen::MatrixXcd direct = last.template cast<std::complex<double>>();
    // Bit for bit: the same code on the same build, and JSON doubles round-trip exactly.
    EXPECT_EQ(app_final, direct);
    EXPECT_EQ(entry["energy_final"].get<double>(), system->energy(last));
    const double err = (last - reference.last).norm();
    EXPECT_NEAR(entry["err_final"].get<double>(), err, 1e-12 * (1.0 + err));
    // The spectrum drift, from Eigen's eigensolver here: equal to round-off of the spectra.
    EXPECT_NEAR(entry["casimir_drift"].get<double>(), direct_run.drift_max, 1e-14);
    const ddb::MethodInfo* info = ddb::findMethod(name);
    EXPECT_EQ(entry["order"], summary["parameters"]["alpha"] == 0.0
                                  ? info->order_without_dissipation
                                  : info->order);
    if (info->keeps_casimirs) {
      EXPECT_LT(entry["casimir_drift"].get<double>(), 1e-13);
    }

    std::string header;
    const auto rows = readCsv(out / (name + ".csv"), &header);
    EXPECT_EQ(header, "t,energy,casimir_drift,norm,h,residual");
    ASSERT_EQ(rows.size(), static_cast<std::size_t>(steps + 1));
    EXPECT_EQ(rows.back()[1], system->energy(last));
    EXPECT_NEAR(rows.back()[2], direct_run.drift_last, 1e-14);
    EXPECT_NEAR(rows.back()[3], last.norm(), 1e-15 * last.norm());
    EXPECT_EQ(rows.front()[2], 0.0);
  }
}

TEST(DdbCompareMatrix, ManakovFromAFileMatchesTheLibrary) {
  // M0 and J chosen here, independent of the app's defaults.
  const int n = 4;
  Eigen::MatrixXd M0(n, n);
  M0 << 0, 0.3, -0.2, 0.5,  //
      -0.3, 0, 0.7, -0.1,   //
      0.2, -0.7, 0, 0.4,    //
      -0.5, 0.1, -0.4, 0;
  const Eigen::Vector4d J(0.9, 1.4, 2.1, 2.6);
  const fs::path out = freshFolder("manakov");
  fs::create_directories(out.parent_path());
  const fs::path file = fs::temp_directory_path() / "ddb_compare_matrix_test_m0.csv";
  {
    std::FILE* f = std::fopen(file.c_str(), "w");
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k < n; ++k) std::fprintf(f, k ? ",%.17g" : "%.17g", M0(i, k));
      std::fprintf(f, "\n");
    }
    std::fclose(f);
  }
  const AppResult r =
      run("--quiet --system manakov --mu0-file " + file.string() +
          " --j 0.9,1.4,2.1,2.6 --alpha 0.3 --h 0.1 --t-end 1 --repeat 1 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const Json summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["system"], "manakov");
  EXPECT_EQ(summary["scenario"], "custom");
  EXPECT_EQ(summary["parameters"]["n"], n);
  EXPECT_EQ(summary["parameters"]["mu0_file"], file.string());
  EXPECT_TRUE(summary["parameters"]["seed"].is_null());
  // A real state: the imaginary parts are zero.
  for (const auto& row : summary["methods"]["ddb-cay"]["final"]["im"]) {
    for (const auto& v : row) EXPECT_EQ(v.get<double>(), 0.0);
  }
  expectMethodsMatchTheLibrary<ddb::SON>(out, ddb::makeManakovBody(J, 0.3), M0, 0.1, 10);
  fs::remove(file);
}

TEST(DdbCompareMatrix, ManakovDefaultsAreTheDocumentedOnes) {
  // docs/reference/command-lines-and-files.md: J_i = 1 + (i − 1)/(N − 1), M0 the real part of the
  // seeded random vorticity scaled to ‖M0‖_F = √N, α = 0.5.
  const int n = 3;
  const fs::path out = freshFolder("manakov-defaults");
  ASSERT_EQ(
      run("--quiet --system manakov --n 3 --seed 7 --t-end 0.5 --repeat 1 --out " + out.string())
          .status,
      0);
  const Json summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["parameters"]["j"], Json::array({1.0, 1.5, 2.0}));
  EXPECT_EQ(summary["parameters"]["alpha"], 0.5);
  EXPECT_EQ(summary["parameters"]["seed"], 7);
  const Eigen::MatrixXd real = ddb::randomVorticity(n, 7).real();
  const Eigen::MatrixXd M0 = real * (std::sqrt(3.0) / real.norm());
  expectMethodsMatchTheLibrary<ddb::SON>(out, ddb::makeManakovBody(Eigen::Vector3d(1, 1.5, 2), 0.5),
                                         M0, 0.1, 5);
}

TEST(DdbCompareMatrix, ZeitlinFromEveryInitMatchesTheLibrary) {
  const int n = 5;
  for (const std::string init : {"random", "l1"}) {
    SCOPED_TRACE(init);
    const fs::path out = freshFolder("zeitlin-" + init);
    ASSERT_EQ(run("--quiet --system zeitlin --n 5 --init " + init +
                  " --seed 3 --alpha 0.4 --h 0.05 --t-end 0.5 --repeat 1 --out " + out.string())
                  .status,
              0);
    const Json summary = readJson(out / "summary.json");
    EXPECT_EQ(summary["system"], "zeitlin");
    EXPECT_EQ(summary["parameters"]["init"], init);
    const Eigen::MatrixXcd W0 =
        init == "random" ? ddb::randomVorticity(n, 3) : ddb::l1Vorticity(n, 3);
    expectMethodsMatchTheLibrary<ddb::SUN>(out, ddb::makeZeitlinFluid(n, 0.4), W0, 0.05, 10);
  }
}

TEST(DdbCompareMatrix, ZeitlinReadsFluidRelaxsLayout) {
  // W0 written here in the layout of --init-file (row j: Re W[j, :] then Im W[j, :]).
  const int n = 4;
  const Eigen::MatrixXcd W0 = ddb::randomVorticity(n, 11);
  const fs::path file = fs::temp_directory_path() / "ddb_compare_matrix_test_w0.csv";
  {
    std::FILE* f = std::fopen(file.c_str(), "w");
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < 2 * n; ++k) {
        std::fprintf(f, k ? ",%.17g" : "%.17g", k < n ? W0(j, k).real() : W0(j, k - n).imag());
      }
      std::fprintf(f, "\n");
    }
    std::fclose(f);
  }
  const fs::path out = freshFolder("zeitlin-file");
  ASSERT_EQ(run("--quiet --system zeitlin --init-file " + file.string() +
                " --h 0.1 --t-end 0.5 --repeat 1 --out " + out.string())
                .status,
            0);
  const Json summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["parameters"]["init"], "file");
  EXPECT_EQ(summary["parameters"]["n"], n);
  expectMethodsMatchTheLibrary<ddb::SUN>(out, ddb::makeZeitlinFluid(n, 0.5), W0, 0.1, 5);
  fs::remove(file);
}

TEST(DdbCompareMatrix, SweepWritesAFallingErrorForEveryMethod) {
  const fs::path out = freshFolder("sweep");
  ASSERT_EQ(run("--quiet --system manakov --n 3 --t-end 1 --repeat 1 --sweep-h 0.025:0.1:3 --out " +
                out.string())
                .status,
            0);
  std::string header;
  std::ifstream in(out / "error_vs_h.csv");
  std::getline(in, header);
  EXPECT_EQ(header, "method,h,err_final,casimir_drift,runtime_s");
  std::map<std::string, std::vector<double>> errors;
  for (std::string line; std::getline(in, line);) {
    std::stringstream ss(line);
    std::string method, h, err;
    std::getline(ss, method, ',');
    std::getline(ss, h, ',');
    std::getline(ss, err, ',');
    errors[method].push_back(std::stod(err));
  }
  EXPECT_EQ(errors.size(), ddb::methodNames(ddb::kMatrixGroups).size() - 1);  // no reference
  for (const auto& [method, e] : errors) {
    ASSERT_EQ(e.size(), 3u) << method;
    if (e[0] < 1e-12) {  // already at the round-off plateau at the largest h (ddb6-exp)
      EXPECT_LT(e[2], 1e-12) << method;
      continue;
    }
    EXPECT_LT(e[2], e[0]) << method;
  }
}

TEST(DdbCompareMatrix, WithoutDissipationTheOrdersAreTheTablesOrdersAtAlphaZero) {
  const fs::path out = freshFolder("alpha0");
  ASSERT_EQ(
      run("--quiet --system zeitlin --n 3 --alpha 0 --t-end 0.3 --repeat 1 --out " + out.string())
          .status,
      0);
  expectMethodsMatchTheLibrary<ddb::SUN>(out, ddb::makeZeitlinFluid(3, 0.0),
                                         ddb::randomVorticity(3, 1), 0.1, 3);
}

TEST(DdbCompareMatrix, PlotDrawsTheCasimirSweepAndWorkPrecisionFigures) {
  for (const std::string system : {"manakov", "zeitlin"}) {
    const fs::path out = freshFolder("plot-" + system);
    const AppResult r =
        run("--quiet --system " + system +
            " --n 3 --t-end 0.5 --repeat 1 --sweep-h 0.05:0.1:2 --plot --out " + out.string());
    ASSERT_EQ(r.status, 0) << system << ": " << r.output;
    for (const std::string figure : {"casimir_vs_t", "error_vs_h", "work_precision"}) {
      EXPECT_TRUE(fs::is_regular_file(out / (figure + ".png"))) << system << " " << figure;
    }
  }
}

TEST(DdbCompareMatrix, BadInputExitsTwoNamingTheFlagAndWritesNothing) {
  const fs::path files = freshFolder("files");
  fs::create_directories(files);
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(files / name) << text;
    return (files / name).string();
  };
  const std::string rect = write("rect.csv", "0,1,2\n-1,0,3\n");
  const std::string symmetric = write("symmetric.csv", "0,1,2\n1,0,3\n2,3,0\n");
  std::string big;  // 65 × 65 zeros but for one skew pair: N above the cap
  for (int i = 0; i < 65; ++i) {
    for (int k = 0; k < 65; ++k)
      big += std::string(k ? "," : "") + (i == 0 && k == 1 ? "1" : i == 1 && k == 0 ? "-1" : "0");
    big += "\n";
  }
  const std::string large = write("large.csv", big);
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--system manakov --n 1", "--n = 1"},
      {"--system manakov --n 100000", "--n = 100000"},
      {"--system zeitlin --n 100000", "--n = 100000"},
      {"--system zeitlin --n 1", "--n = 1"},
      {"--system manakov --n 3 --j 1,2", "--j = 1,2"},
      {"--system manakov --n 3 --j 1,0,2", "--j = 1,0,2"},
      {"--system manakov --n 3 --j 1,-2,2", "--j = 1,-2,2"},
      {"--system manakov --mu0-file " + files.string() + "/missing.csv", "--mu0-file = "},
      {"--system manakov --mu0-file " + rect, "--mu0-file = "},
      {"--system manakov --mu0-file " + symmetric, "--mu0-file = "},
      {"--system manakov --mu0-file " + large, "--mu0-file = "},
      {"--system manakov --mu0-file " + symmetric + " --seed 2", "--seed = 2"},
      {"--system manakov --init l1", "--init = l1"},
      {"--system manakov --init-file " + rect, "--init-file = "},
      {"--system manakov --inertia 1,2,3", "--inertia = "},
      {"--system manakov --method sddb-paper-cay", "--method = sddb-paper-cay"},
      {"--system zeitlin --j 1,2", "--j = 1,2"},
      {"--system zeitlin --mu0-file " + rect, "--mu0-file = "},
      {"--system zeitlin --init bogus", "--init = bogus"},
      {"--system zeitlin --init-file " + rect, "--init-file = "},
      {"--system zeitlin --init-file " + symmetric, "--init-file = "},
      {"--system zeitlin --scenario B", "--scenario = B"},
      {"--system zeitlin --alpha 1e308", "--alpha = 1e308"},
      {"--system rigid-body --n 4", "--n = 4"},
      {"--system heavy-top --seed 3", "--seed = 3"},
      {"--system kirchhoff --init zonal", "--init = zonal"}};
  for (const auto& [arguments, flag] : cases) {
    const fs::path out = freshFolder("bad");
    const AppResult r = run(arguments + " --t-end 0.2 --out " + out.string());
    EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output;
    EXPECT_THAT(r.error, ::testing::HasSubstr(flag)) << arguments;
    EXPECT_EQ(std::count(r.error.begin(), r.error.end(), '\n'), 1) << arguments << r.error;
    EXPECT_FALSE(fs::exists(out)) << arguments;
  }
  fs::remove_all(files);
}

TEST(DdbCompareMatrix, TheCapOnNSaysWhy) {
  const AppResult r = run("--system zeitlin --n 65 --out " + freshFolder("cap").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.error, ::testing::HasSubstr("--n = 65: must be in [2, 64]"));
  EXPECT_THAT(r.error, ::testing::HasSubstr("reference"));
  EXPECT_THAT(r.error, ::testing::HasSubstr("O(N^3)"));
}

}  // namespace ddb_compare_matrix_tests
