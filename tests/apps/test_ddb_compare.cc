// ddb-compare end to end on a short horizon: the files against the contract of
// docs/reference/command-lines-and-files.md (columns, row count, JSON keys, finite values), the
// final state against the library called directly, bad input (exit status 2, a message naming the
// flag, nothing written), --help, --version, "custom" scenarios, --every, FAILED runs,
// I/O errors (exit status 1 naming the file) and constant memory on long runs.
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/planar_kirchhoff.h>
#include <ddb/systems/rigid_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gmock/gmock.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <sstream>

#include "app_test_support.h"
#include "ddb_compare/system_table.h"

namespace ddb_compare_tests {

using namespace ddb::test;
using Json = nlohmann::ordered_json;

AppResult run(const std::string& arguments) { return runProgram(DDB_COMPARE_PATH, arguments); }

int runApp(const std::string& arguments) { return run("--quiet " + arguments).status; }

fs::path freshFolder(const std::string& name) {
  return ddb::test::freshFolder("ddb_compare_test_", name);
}

// A run folder holds one run (docs/reference/command-lines-and-files.md, "ddb-compare"): a second
// run into a finished folder is refused and changes nothing; with --overwrite it replaces the
// first run's files, all of them, and keeps the files ddb-compare does not write.
TEST(DdbCompare, ASecondRunIntoAFinishedFolderIsRefusedOrReplacesTheFirst) {
  const fs::path out = freshFolder("second_run");
  ASSERT_EQ(runApp("--t-end 1 --method ddb-cay,rk4 --repeat 1 --out " + out.string()), 0);
  std::ofstream(out / "notes.txt") << "the user's own file\n";
  const std::string first_csv = readFile(out / "ddb-cay.csv");
  const std::string first_summary = readFile(out / "summary.json");

  const AppResult refused =
      run("--quiet --t-end 1 --h 0.05 --method ddb-cay --repeat 1 --out " + out.string());
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_THAT(refused.error, ::testing::HasSubstr("another run's files"));
  EXPECT_THAT(refused.error, ::testing::HasSubstr("--overwrite"));
  EXPECT_THAT(refused.error, ::testing::Not(::testing::HasSubstr("--resume")));
  EXPECT_EQ(std::count(refused.error.begin(), refused.error.end(), '\n'), 1) << refused.error;
  EXPECT_EQ(readFile(out / "ddb-cay.csv"), first_csv);
  EXPECT_EQ(readFile(out / "summary.json"), first_summary);
  EXPECT_TRUE(fs::exists(out / "rk4.csv"));

  ASSERT_EQ(
      runApp("--t-end 1 --h 0.05 --method ddb-cay --repeat 1 --overwrite --out " + out.string()),
      0);
  EXPECT_FALSE(fs::exists(out / "rk4.csv"));  // the first run's, which the summary would not list
  EXPECT_EQ(readJson(out / "summary.json")["h"], 0.05);
  EXPECT_EQ(readJson(out / "summary.json")["methods"].size(), 1u);
  EXPECT_EQ(readFile(out / "notes.txt"), "the user's own file\n");
}

TEST(DdbCompare, AdaptiveTakesAnyFirstStepAndGrowsIt) {
  // --h is only the first step with --adaptive: 1e-300 runs to the time cap, where it was
  // refused as "more than 1e9 steps"; without --adaptive it is refused, naming --adaptive.
  const fs::path out = freshFolder("tiny_first_step");
  ASSERT_EQ(
      runApp("--adaptive --h 1e-300 --t-end 5 --method ddb-cay --repeat 1 --out " + out.string()),
      0);
  const auto method = readJson(out / "summary.json")["methods"]["ddb-cay"];
  EXPECT_EQ(method["stop"], "time cap");
  EXPECT_NEAR(method["t_final"].get<double>(), 5.0, 1e-12);
  EXPECT_GT(method["h_final"].get<double>(), 1e-3);
  const AppResult refused = run("--h 1e-300 --t-end 5 --out " + (out / "fixed").string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_THAT(refused.error, ::testing::HasSubstr("--adaptive, whose --h is only the first step"));
}

TEST(DdbCompare, WritesContractFilesMatchingTheLibrary) {
  const fs::path out = freshFolder("contract");
  ASSERT_EQ(runApp("--scenario B --t-end 2 --h 0.1 --method ddb-cay,rk4 --out " + out.string()), 0);
  for (const std::string method : {"ddb-cay", "rk4"}) {
    std::string header;
    const auto rows = readCsv(out / (method + ".csv"), &header);
    EXPECT_EQ(header, "t,m1,m2,m3,energy,casimir,h,residual");
    ASSERT_EQ(rows.size(), 21u);  // t = 0, 0.1, ..., 2
    for (const auto& row : rows) {
      ASSERT_EQ(row.size(), 8u);
      for (double v : row) EXPECT_TRUE(std::isfinite(v));
    }
    // The library called directly gives the same final state.
    const Eigen::Vector3d inertia(1.0, 1.3, 0.5);
    auto body = ddb::makeRigidBody(inertia, 0.5);
    auto integrator = ddb::makeMethod<ddb::SO3>(method, body);
    Eigen::Vector3d last;
    ddb::integrate(*integrator, inertia.cwiseProduct(Eigen::Vector3d(0, 0.05, 1)), 0.0, 0.1, 20,
                   [&](long, double, const Eigen::Vector3d& mu) { last = mu; });
    const auto& final_row = rows.back();
    EXPECT_NEAR(final_row[0], 2.0, 1e-12);
    for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(final_row[1 + i], last(i)) << method;
    EXPECT_DOUBLE_EQ(final_row[4], body->energy(last));
  }
  Json summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["system"], "rigid-body");
  EXPECT_EQ(summary["scenario"], "B");
  EXPECT_EQ(summary["h"], 0.1);
  EXPECT_NEAR(summary["t_end"].get<double>(), 2.0, 1e-12);
  EXPECT_EQ(summary["steps"], 20);
  for (const std::string method : {"ddb-cay", "rk4"}) {
    Json& entry = summary["methods"][method];
    for (const std::string key :
         {"final", "energy_final", "err_final", "casimir_drift", "runtime_s"}) {
      ASSERT_TRUE(entry.contains(key)) << method << " " << key;
      for (const Json& value : entry[key].is_array() ? entry[key] : Json::array({entry[key]})) {
        EXPECT_TRUE(value.is_number()) << method << " " << key;  // null: not finite
      }
    }
  }
  EXPECT_FALSE(fs::exists(out / "ddb-cay.csv.tmp"));
}

TEST(DdbCompare, SweepWritesErrorVersusStepSize) {
  const fs::path out = freshFolder("sweep");
  ASSERT_EQ(runApp("--t-end 2 --method ddb-cay,rk4 --repeat 1 --sweep-h 0.01:0.1:4 --out " +
                   out.string()),
            0);
  std::ifstream in(out / "error_vs_h.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "method,h,err_final,casimir_drift,runtime_s");
  std::map<std::string, std::vector<std::pair<double, double>>> errors;
  for (std::string line; std::getline(in, line);) {
    std::stringstream ss(line);
    std::string method, h, err;
    std::getline(ss, method, ',');
    std::getline(ss, h, ',');
    std::getline(ss, err, ',');
    errors[method].push_back({std::stod(h), std::stod(err)});
  }
  ASSERT_EQ(errors.size(), 2u);
  for (const auto& [method, points] : errors) {
    ASSERT_EQ(points.size(), 4u) << method;
    EXPECT_NEAR(points.front().first, 0.1, 1e-15);
    EXPECT_NEAR(points.back().first, 0.01, 1e-15);
    for (size_t i = 1; i < points.size(); ++i) {
      EXPECT_LT(points[i].second, points[i - 1].second) << method << ": error must fall with h";
    }
  }
}

TEST(DdbCompare, SE3SystemsWriteTwoCasimirColumns) {
  for (const std::string system : {"heavy-top", "kirchhoff"}) {
    const fs::path out = freshFolder(system);
    ASSERT_EQ(runApp("--system " + system + " --t-end 1 --repeat 1 --out " + out.string()), 0);
    std::string header;
    const auto rows = readCsv(out / "ddb-cay.csv", &header);
    EXPECT_EQ(header, "t,m1,m2,m3,m4,m5,m6,energy,casimir1,casimir2,h,residual");
    EXPECT_EQ(rows.size(), 11u);
    Json summary = readJson(out / "summary.json");
    EXPECT_EQ(summary["system"], system);
    for (const std::string method : {"ddb-cay", "ddb-exp", "ddb-exp-exact", "rk4", "lobatto3c"}) {
      EXPECT_TRUE(summary["methods"].contains(method)) << method;
    }
  }
}

TEST(DdbCompare, PlanarKirchhoffWritesItsStateAndCasimirAndMatchesTheLibrary) {
  // Kirchhoff's body in the plane on SE(2): three coordinates and one Casimir, |P|²; the final
  // state against the library called directly with the parameters given.
  const fs::path out = freshFolder("planar");
  ASSERT_EQ(runApp("--system planar-kirchhoff --inertia 0.7 --mass 1,2 --mu0 0.3,1,0.2 "
                   "--t-end 3 --h 0.1 --method ddb-cay,sddb-cay,rk4 --repeat 1 --out " +
                   out.string()),
            0);
  const auto body =
      ddb::makePlanarKirchhoffBody(0.7, Eigen::Vector2d(1.0, 2.0), 0.5, Eigen::Vector3d::Ones());
  const Eigen::Vector3d mu0(0.3, 1.0, 0.2);
  for (const std::string method : {"ddb-cay", "sddb-cay", "rk4"}) {
    std::string header;
    const auto rows = readCsv(out / (method + ".csv"), &header);
    EXPECT_EQ(header, "t,m1,m2,m3,energy,casimir,h,residual");
    ASSERT_EQ(rows.size(), 31u);
    auto integrator = ddb::makeMethod<ddb::SE2>(method, body);
    Eigen::Vector3d last;
    ddb::integrate(*integrator, mu0, 0.0, 0.1, 30,
                   [&](long, double, const Eigen::Vector3d& mu) { last = mu; });
    for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(rows.back()[1 + i], last(i)) << method;
    EXPECT_DOUBLE_EQ(rows.back()[4], body->energy(last)) << method;
    // |P|² = 1.04 on every row of the DDB methods, and their energy never rises.
    if (method == "rk4") continue;
    for (size_t k = 0; k < rows.size(); ++k) {
      EXPECT_NEAR(rows[k][5], 1.04, 1e-14) << method << " row " << k;
      if (k > 0) {
        EXPECT_LE(rows[k][4], rows[k - 1][4]) << method << " row " << k;
      }
    }
  }
  Json summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["system"], "planar-kirchhoff");
  EXPECT_EQ(summary["scenario"], "custom");
  EXPECT_EQ(summary["parameters"]["inertia"], 0.7);
  EXPECT_EQ(summary["parameters"]["mass"], Json::array({1.0, 2.0}));
}

TEST(DdbCompare, PlanarKirchhoffRefusesTheShapesOfTheOtherSystems) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--inertia 1,2,3", "--inertia"}, {"--inertia 0", "--inertia"},
      {"--mass 1,2,3", "--mass"},       {"--mass 1,-2", "--mass"},
      {"--mu0 1,2,3,4,5,6", "--mu0"},   {"--metric 1,1,1,1,1,1", "--metric"},
      {"--metric 1,-1,1", "--metric"},  {"--mgl 2", "--mgl"}};
  for (const auto& [arguments, flag] : cases) {
    const fs::path out = freshFolder("planar_bad");
    const AppResult r =
        run("--system planar-kirchhoff " + arguments + " --t-end 1 --out " + out.string());
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_THAT(r.output, ::testing::HasSubstr(flag + " = ")) << arguments;
    EXPECT_FALSE(fs::exists(out)) << arguments;
  }
}

TEST(DdbCompare, FailedSolveKeepsThePrefixAndExitsOne) {
  // Energy ascent (α = −0.5) from Ω₀ near the slow axis: |Ω| grows until an exp step of
  // h = 4 passes the injectivity limit h|ξ| = π (docs/reference/guarantees.md §2) after some good
  // steps; the valid prefix is written. Independent expectation: the step at which the
  // library's own integrate() fails.
  const Eigen::Vector3d inertia(1.0, 1.3, 0.5), omega0(0.05, 0.4, 0.1);
  auto exact = ddb::makeMethod<ddb::SO3>("ddb-exp-exact", ddb::makeRigidBody(inertia, -0.5));
  long failed_step = -1;
  try {
    ddb::integrate(*exact, inertia.cwiseProduct(omega0), 0.0, 4.0, 40,
                   [](long, double, const Eigen::Vector3d&) {});
  } catch (const ddb::InjectivityLimit& failure) {
    failed_step = failure.step();
  }
  ASSERT_GT(failed_step, 0);
  const fs::path out = freshFolder("failure");
  ASSERT_EQ(runApp("--method ddb-exp-exact --alpha -0.5 --omega0 0.05,0.4,0.1 --h 4 --t-end 160 "
                   "--repeat 1 --out " +
                   out.string()),
            1);
  std::string header;
  const auto rows = readCsv(out / "ddb-exp-exact.csv", &header);
  EXPECT_EQ(rows.size(), static_cast<std::size_t>(failed_step + 1));
  for (const auto& row : rows)
    for (double v : row) EXPECT_TRUE(std::isfinite(v));
  Json entry = readJson(out / "summary.json")["methods"]["ddb-exp-exact"];
  EXPECT_THAT(
      entry["failure"].get<std::string>(),
      ::testing::StartsWith("DDB with the exp retraction step " + std::to_string(failed_step)));
  EXPECT_THAT(entry["failure"].get<std::string>(), ::testing::HasSubstr("injectivity limit"));
  EXPECT_TRUE(entry["err_final"].is_null());
}

TEST(DdbCompare, BadInputExitsTwoAndWritesNothing) {
  const std::vector<std::string> bad{
      "--system pendulum", "--scenario D",     "--method ddb-foo", "--h 0",
      "--h -0.1",          "--h nan",          "--t-end 0",        "--t-end 1e12 --h 1e-3",
      "--inertia 1,-1,2",  "--inertia 1,2",    "--inertia 1,x,2",  "--omega0 0,0",
      "--alpha nan",       "--every 0",        "--repeat 0",       "--sweep-h 0.1:0.01:3",
      "--mass 1,2,3",      "--verbose --quiet"};
  for (const auto& arguments : bad) {
    const fs::path out = freshFolder("bad");
    EXPECT_EQ(runApp(arguments + " --out " + out.string()), 2) << arguments;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << arguments;
  }
  EXPECT_EQ(runApp("--t-end 1 --out /proc/ddb-cannot-write"), 2);
}

TEST(DdbCompare, VersionIsTheProjectVersion) {
  const AppResult r = run("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output, std::string("ddb-compare ") + DDB_PROJECT_VERSION + "\n");
}

TEST(DdbCompare, HelpListsEveryMethodSystemScenarioAndDefault) {
  const AppResult r = run("--help");
  EXPECT_EQ(r.status, 0);
  const auto hasLine = [&](const std::string& name) {
    return std::regex_search(r.output, std::regex("\n  " + name + " +[A-Za-z(]"));
  };
  for (const auto& method : ddb::methodNames()) EXPECT_TRUE(hasLine(method)) << method;
  for (const std::string system :
       {"rigid-body", "heavy-top", "kirchhoff", "planar-kirchhoff", "manakov", "zeitlin"}) {
    EXPECT_TRUE(hasLine(system)) << system;
  }
  for (const std::string init : {"random", "l1", "zonal"}) EXPECT_TRUE(hasLine(init)) << init;
  for (const std::string scenario : {"A", "B", "C"}) EXPECT_TRUE(hasLine(scenario)) << scenario;
  // Defaults of docs/reference/command-lines-and-files.md and of the paper's scenarios (Section 5).
  for (const std::string text :
       {"--h TEXT=0.1", "--out TEXT=results", "--system TEXT=rigid-body", "--scenario TEXT=A",
        "--every INT=1", "--repeat INT=5", "A 30", "B and C 250", "1,1.3,0.5", "C 1,1,0.5",
        "0,0.05,1", "(default 0.5)", "mass 1,2,3", "mgl 1", "chi 0,0,1", "metric 1,1,1,1,1,1",
        "planar-kirchhoff  inertia 0.5, mass 1,3, mu0 0.3,1,0.2, metric 1,1,1"}) {
    EXPECT_THAT(r.output, ::testing::HasSubstr(text));
  }
}

TEST(DdbCompare, UnknownNamesListTheValidOnes) {
  const fs::path out = freshFolder("unknown");
  AppResult r = run("--method ddb-cay,ddb-foo --out " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, ::testing::HasSubstr("--method = ddb-foo"));
  for (const auto& method : ddb::methodNames()) EXPECT_THAT(r.output, ::testing::HasSubstr(method));
  r = run("--scenario D --out " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, ::testing::HasSubstr("A, B, C"));
  r = run("--system pendulum --out " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, ::testing::HasSubstr("rigid-body, heavy-top, kirchhoff"));
  EXPECT_FALSE(fs::exists(out));
}

/// A value of each system flag that its systems accept as text (a file need not exist).
std::string sampleValue(std::string_view flag) {
  static const std::map<std::string_view, std::string> values{{"--scenario", "A"},
                                                              {"--inertia", "1,2,3"},
                                                              {"--omega0", "0,0,1"},
                                                              {"--mu0", "1,2,3,4,5,6"},
                                                              {"--mgl", "2"},
                                                              {"--chi", "0,0,1"},
                                                              {"--metric", "1,1,1,1,1,1"},
                                                              {"--mass", "1,2,3"},
                                                              {"--n", "4"},
                                                              {"--j", "1,2,3,4"},
                                                              {"--mu0-file", "none.csv"},
                                                              {"--seed", "3"},
                                                              {"--init", "zonal"},
                                                              {"--init-file", "none.csv"}};
  return values.at(flag);
}

// The system table (apps/ddb_compare/system_table.h) against the app: every system refuses
// each system flag its row does not name, as bad input naming the flag and the system, with
// nothing written; takes each flag its row names (no such refusal); and --help names, for
// each system flag, exactly the systems that take it, and every system under --system.
TEST(DdbCompare, EverySystemTakesTheFlagsOfItsRowAndRefusesTheOthers) {
  using ddb::compare::kSystemFlags;
  using ddb::compare::systemTable;
  const AppResult help = run("--help");
  for (const auto& row : systemTable()) {
    const std::string system(row.name);
    EXPECT_THAT(help.output, ::testing::HasSubstr("  " + system + "  ")) << system;
    for (const auto& flag : kSystemFlags) {
      const std::string name(flag.name);
      const fs::path out = freshFolder("table");
      const std::string arguments =
          "--system " + system + " " + name + " " + sampleValue(flag.name) +
          " --t-end 0.05 --method ddb-cay --repeat 1 --out " + out.string();
      const AppResult r = run("--quiet " + arguments);
      if (row.takes(flag.name)) {
        EXPECT_THAT(r.output, ::testing::Not(::testing::HasSubstr("does not apply"))) << arguments;
        continue;
      }
      EXPECT_EQ(r.status, 2) << arguments;
      EXPECT_THAT(r.output, ::testing::HasSubstr(name + " = " + sampleValue(flag.name) +
                                                 ": does not apply to --system " + system))
          << arguments;
      EXPECT_FALSE(fs::exists(out)) << arguments;
    }
  }
  for (const auto& flag : kSystemFlags) {
    std::string takers;
    for (const auto& row : systemTable()) {
      if (row.takes(flag.name)) takers += (takers.empty() ? "" : ", ") + std::string(row.name);
    }
    ASSERT_FALSE(takers.empty()) << flag.name << " is taken by no system";
    // CLI11 prints "  --flag TEXT  <help>": the help starts with the systems taking it.
    EXPECT_TRUE(std::regex_search(
        help.output, std::regex("\n  " + std::string(flag.name) + " [^ ]+ +" + takers + ": ")))
        << flag.name << " should say " << takers;
  }
}

TEST(DdbCompare, FlagsThatDoNotApplyAreBadInputNamingTheFlag) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--mgl 2", "--mgl"},
      {"--mass 1,2,3", "--mass"},
      {"--chi 0,0,1", "--chi"},
      {"--metric 1,1,1,1,1,1", "--metric"},
      {"--mu0 1,2,3,4,5,6", "--mu0"},
      {"--system heavy-top --scenario B", "--scenario"},
      {"--system heavy-top --scenario A", "--scenario"},
      {"--system heavy-top --omega0 0,0,1", "--omega0"},
      {"--system heavy-top --mass 1,2,3", "--mass"},
      {"--system kirchhoff --mgl 2", "--mgl"},
      {"--system kirchhoff --omega0 0,0,1", "--omega0"}};
  for (const auto& [arguments, flag] : cases) {
    const fs::path out = freshFolder("inapplicable");
    const AppResult r = run(arguments + " --t-end 0.2 --out " + out.string());
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_THAT(r.output, ::testing::HasSubstr(flag + " = ")) << arguments;
    EXPECT_THAT(r.output, ::testing::HasSubstr("does not apply")) << arguments;
    EXPECT_FALSE(fs::exists(out)) << arguments;
  }
}

TEST(DdbCompare, NonFiniteValuesInMessagesAreNanOrInf) {
  const fs::path out = freshFolder("nonfinite");
  for (const std::string value : {"inf", "nan", "-inf"}) {
    const AppResult r = run("--h " + value + " --out " + out.string());
    EXPECT_EQ(r.status, 2);
    EXPECT_THAT(r.output, ::testing::HasSubstr("--h = " + value));
    EXPECT_THAT(r.output, ::testing::Not(::testing::HasSubstr("null")));
  }
}

TEST(DdbCompare, ParametersThatChangeTheScenarioAreRecordedAsCustom) {
  const fs::path out = freshFolder("custom");
  ASSERT_EQ(runApp("--scenario B --alpha 0.25 --t-end 0.2 --method ddb-cay --repeat 1 --out " +
                   out.string()),
            0);
  Json summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["scenario"], "custom");
  EXPECT_EQ(summary["scenario_base"], "B");
  EXPECT_EQ(summary["parameters"]["alpha"], 0.25);
  EXPECT_EQ(summary["parameters"]["inertia"], Json::array({1, 1.3, 0.5}));  // scenario B's 𝕀
  // The run used α = 0.25: the library called directly ends where the app ended.
  const Eigen::Vector3d inertia(1.0, 1.3, 0.5);
  auto body = ddb::makeRigidBody(inertia, 0.25);
  auto ddb = ddb::makeMethod<ddb::SO3>("ddb-cay", body);
  Eigen::Vector3d last;
  ddb::integrate(*ddb, inertia.cwiseProduct(Eigen::Vector3d(0, 0.05, 1)), 0.0, 0.1, 2,
                 [&](long, double, const Eigen::Vector3d& mu) { last = mu; });
  std::string header;
  const auto rows = readCsv(out / "ddb-cay.csv", &header);
  ASSERT_EQ(rows.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(rows.back()[1 + i], last(i));

  // The scenario's own values given explicitly leave it as it is.
  ASSERT_EQ(runApp("--scenario C --inertia 1,1,0.5 --alpha 0.5 --omega0 0,0.05,1 --t-end 0.2 "
                   "--method ddb-cay --repeat 1 --overwrite --out " +
                   out.string()),
            0);
  summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["scenario"], "C");
  EXPECT_FALSE(summary.contains("scenario_base"));

  ASSERT_EQ(runApp("--system heavy-top --mgl 2 --t-end 0.2 --method ddb-cay --repeat 1 "
                   "--overwrite --out " +
                   out.string()),
            0);
  summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["scenario"], "custom");
  EXPECT_EQ(summary["parameters"]["mgl"], 2.0);
  for (const std::string key : {"inertia", "alpha", "metric", "mu0", "chi"}) {
    EXPECT_TRUE(summary["parameters"].contains(key)) << key;
  }
}

TEST(DdbCompare, EveryWritesEveryKthStateAndTheLast) {
  // t = 0, 0.1, ..., 1 (10 steps): every 3rd state is t = 0, 0.3, 0.6, 0.9, and then the
  // last, t = 1; every 5th is t = 0, 0.5, 1 (the last is a multiple).
  for (const auto& [every, times] : std::vector<std::pair<int, std::vector<double>>>{
           {3, {0.0, 0.3, 0.6, 0.9, 1.0}}, {5, {0.0, 0.5, 1.0}}, {20, {0.0, 1.0}}}) {
    const fs::path out = freshFolder("every");
    ASSERT_EQ(runApp("--t-end 1 --method ddb-cay,rk4 --repeat 1 --every " + std::to_string(every) +
                     " --out " + out.string()),
              0);
    for (const std::string method : {"ddb-cay", "rk4"}) {
      std::string header;
      const auto rows = readCsv(out / (method + ".csv"), &header);
      ASSERT_EQ(rows.size(), times.size()) << method << " every " << every;
      for (size_t i = 0; i < rows.size(); ++i) EXPECT_NEAR(rows[i][0], times[i], 1e-12);
    }
    EXPECT_EQ(readJson(out / "summary.json")["steps"], 10);
  }
}

TEST(DdbCompare, TEndNotAMultipleOfHIsReportedAndTheReachedOneRecorded) {
  const fs::path out = freshFolder("t_end");
  const AppResult r = run("--t-end 1 --h 0.3 --method ddb-cay --repeat 1 --out " + out.string());
  ASSERT_EQ(r.status, 0);
  EXPECT_THAT(r.output, ::testing::HasSubstr("not a multiple"));
  Json summary = readJson(out / "summary.json");
  EXPECT_NEAR(summary["t_end"].get<double>(), 0.9, 1e-12);  // 3 steps of 0.3
  EXPECT_EQ(summary["t_end_requested"], 1.0);
  std::string header;
  const auto rows = readCsv(out / "ddb-cay.csv", &header);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_NEAR(rows.back()[0], 0.9, 1e-12);
  // A multiple says nothing.
  EXPECT_THAT(run("--t-end 1 --h 0.25 --method ddb-cay --repeat 1 --out " + out.string()).output,
              ::testing::Not(::testing::HasSubstr("not a multiple")));
}

TEST(DdbCompare, FailedMethodsAreMarkedFailedEverywhere) {
  // Independent expectation: the step at which the library's own integrate() fails.
  const Eigen::Vector3d inertia(1.0, 1.3, 0.5);
  auto exact = ddb::makeMethod<ddb::SO3>("ddb-exp-exact", ddb::makeRigidBody(inertia, 0.5));
  long failed_step = -1;
  try {
    ddb::integrate(*exact, inertia.cwiseProduct(Eigen::Vector3d(0, 0.05, 1)), 0.0, 10.0, 40,
                   [](long, double, const Eigen::Vector3d&) {});
  } catch (const ddb::SolveFailure& failure) {
    failed_step = failure.step();
  }
  ASSERT_GE(failed_step, 0);
  const std::string failed = "FAILED at step " + std::to_string(failed_step);

  const fs::path out = freshFolder("failed");
  const AppResult r =
      run("--method ddb-exp-exact,ddb-cay --h 10 --t-end 400 --repeat 1 --out " + out.string());
  ASSERT_EQ(r.status, 1);
  EXPECT_THAT(r.output, ::testing::HasSubstr("ddb-exp-exact"));
  EXPECT_THAT(r.output, ::testing::HasSubstr(failed));
  const std::string table = readFile(out / "runtime_table.md");
  EXPECT_TRUE(std::regex_search(table, std::regex("\\| ddb-exp-exact \\| " + failed + " \\|")))
      << table;
  EXPECT_TRUE(std::regex_search(table, std::regex("\\| ddb-cay \\| [0-9.e+-]+ \\|"))) << table;
  Json summary = readJson(out / "summary.json");
  Json& entry = summary["methods"]["ddb-exp-exact"];
  EXPECT_EQ(entry["status"], "FAILED");
  EXPECT_EQ(entry["failed_step"], failed_step);
  EXPECT_EQ(entry["steps"], failed_step);
  EXPECT_TRUE(entry["casimir_drift"].is_null());
  EXPECT_TRUE(entry["runtime_s"].is_null());
  EXPECT_EQ(summary["runtime_table"]["ddb-exp-exact"], failed);
  EXPECT_EQ(summary["methods"]["ddb-cay"]["status"], "ok");
}

TEST(DdbCompare, ExpStepPastItsLimitIsARunFailureNotBadInput) {
  // The heavy top's exp method cannot take h = 2 (|hξ| reaches π, or its dexp⁻¹ series
  // runs out of terms): the rk4 file is written, so the exit status must be 1 (a run
  // failed), not 2 (bad input, nothing written).
  const fs::path out = freshFolder("dexp");
  const AppResult r =
      run("--system heavy-top --method rk4,ddb-exp-exact --h 2 --repeat 1 --out " + out.string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(fs::exists(out / "rk4.csv"));
  EXPECT_EQ(readJson(out / "summary.json")["methods"]["ddb-exp-exact"]["status"], "FAILED");
}

TEST(DdbCompare, UnwritableFileIsExitOneNamingItAndLeavesNoTemporary) {
  const fs::path out = freshFolder("io");
  fs::create_directories(out / "rk4.csv");  // a folder where the file should go
  const AppResult r = run("--t-end 0.2 --method rk4 --repeat 1 --out " + out.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.output, ::testing::HasSubstr((out / "rk4.csv").string()));
  for (const auto& entry : fs::directory_iterator(out)) {
    // The folder in rk4.csv's place, and the folder's lock (empty: "Run folders").
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "rk4.csv" || (name == "run.lock" && fs::file_size(entry.path()) == 0))
        << "left behind: " << entry.path();
  }
}

TEST(DdbCompare, MemoryDoesNotGrowWithTheNumberOfSteps) {
  // 2e4 and 2e6 steps with --every 1000: the same peak memory (a stored trajectory of
  // 2e6 states would add 2e6 * 24 bytes = 48 MB).
  const fs::path out = freshFolder("memory");
  const AppResult short_run =
      run("--quiet --method rk4 --h 1e-3 --t-end 20 --every 1000 --repeat 1 --out " + out.string());
  const AppResult long_run =
      run("--quiet --method rk4 --h 1e-3 --t-end 2000 --every 1000 "
          "--repeat 1 --overwrite --out " +
          out.string());
  ASSERT_EQ(short_run.status, 0);
  ASSERT_EQ(long_run.status, 0);
  std::string header;
  EXPECT_EQ(readCsv(out / "rk4.csv", &header).size(), 2001u);
  EXPECT_LT(long_run.max_rss_kb, short_run.max_rss_kb + 4096)
      << short_run.max_rss_kb << " kB vs " << long_run.max_rss_kb << " kB";
}

/// r = |M × Ω|/(|M| |Ω|) of the rigid body, Ω = M/𝕀 (docs/guide/steady-states.md), computed
/// here from the written state.
double rigidBodyResidual(const Eigen::Vector3d& inertia, const Eigen::Vector3d& M) {
  const Eigen::Vector3d omega = M.cwiseQuotient(inertia);
  return M.cross(omega).norm() / (M.norm() * omega.norm());
}

TEST(DdbCompare, UntilSteadyAdaptiveReachesScenarioBsLimitPoint) {
  const fs::path out = freshFolder("steady_b");
  constexpr double kTolerance = 1e-11;
  ASSERT_EQ(runApp("--scenario B --method sddb-exp --until-steady 1e-11 --adaptive --t-end 1000 "
                   "--repeat 1 --out " +
                   out.string()),
            0);
  const Eigen::Vector3d inertia(1.0, 1.3, 0.5);
  const Eigen::Vector3d M0 = inertia.cwiseProduct(Eigen::Vector3d(0, 0.05, 1));
  Json summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["until_steady"], kTolerance);
  EXPECT_EQ(summary["adaptive"], true);
  EXPECT_EQ(summary["adaptive_tol"], 0.5);
  Json& entry = summary["methods"]["sddb-exp"];
  EXPECT_EQ(entry["stop"], "steady");
  EXPECT_EQ(entry["steady"], true);
  const Eigen::Vector3d M(entry["final"][0].get<double>(), entry["final"][1].get<double>(),
                          entry["final"][2].get<double>());
  const double r = rigidBodyResidual(inertia, M);
  EXPECT_LE(r, kTolerance);
  EXPECT_NEAR(entry["residual_final"].get<double>(), r, 1e-3 * kTolerance);
  // The closed-form limit point ±|M₀| e₂, and the distance bound from r near it (as in
  // test_relax): |M × Ω| ≥ |M|²|u₂| m √(u₁² + u₃²), m = min(|1/𝕀₃ − 1/𝕀₂|, |1/𝕀₂ − 1/𝕀₁|).
  const Eigen::Vector3d limit = std::copysign(M0.norm(), M(1)) * Eigen::Vector3d::UnitY();
  const double m = std::min(std::abs(1 / inertia(2) - 1 / inertia(1)),
                            std::abs(1 / inertia(1) - 1 / inertia(0)));
  const double u2 = std::abs(M.normalized()(1));
  EXPECT_LE((M - limit).norm(), 1.01 * M0.norm() * r / (u2 * m * inertia.minCoeff()));
  EXPECT_LE((M - limit).norm(), 1e-10);
  // Issue 21's target: at least 10x fewer step attempts than h = 0.1 (2500 steps).
  const long steps = entry["steps"], rejected = entry["steps_rejected"];
  EXPECT_GT(rejected, 0);
  EXPECT_LT(steps + rejected, 250);

  std::string header;
  const auto rows = readCsv(out / "sddb-exp.csv", &header);
  EXPECT_EQ(header, "t,m1,m2,m3,energy,casimir,h,residual");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(steps + 1));
  EXPECT_EQ(rows.front()[6], 0.0);  // no step reached μ₀
  for (size_t k = 0; k < rows.size(); ++k) {
    const auto& row = rows[k];
    const Eigen::Vector3d Mk(row[1], row[2], row[3]);
    EXPECT_NEAR(Mk.norm(), M0.norm(), 1e-14);
    EXPECT_NEAR(row[7], rigidBodyResidual(inertia, Mk), 1e-12 * row[7]) << k;
    // Stopped at the first state within the tolerance; the energy never rose beyond the
    // rounding of an energy difference, 8ε max(|H|, |H'|) (docs/guide/steady-states.md, rule 2).
    if (k + 1 < rows.size()) {
      EXPECT_GT(row[7], kTolerance) << k;
    }
    if (k > 0) {
      EXPECT_LE(row[4] - rows[k - 1][4], 8 * std::numeric_limits<double>::epsilon() *
                                             std::max(std::abs(row[4]), std::abs(rows[k - 1][4])))
          << k;
      EXPECT_NEAR(row[0] - rows[k - 1][0], row[6], 1e-12 * row[0]) << k;
      // h is the first step times a power of two (docs/guide/steady-states.md).
      const double doublings = std::log2(row[6] / 0.1);
      EXPECT_NEAR(doublings, std::round(doublings), 1e-12) << k;
    }
  }
  EXPECT_LE(rows.back()[7], kTolerance);

  // The same as relax() called directly with the flags' options.
  const auto body = ddb::makeRigidBody(inertia, 0.5);
  auto method = ddb::makeMethod<ddb::SO3>("sddb-exp", body);
  ddb::RelaxOptions options;
  options.tolerance = kTolerance;
  options.max_steps = 1000000000L;
  options.t_end = 1000;
  options.control.adaptive = true;
  const auto direct = ddb::relax(*method, *body, M0, 0.1, options);
  EXPECT_EQ(direct.last.k, steps);
  EXPECT_EQ(direct.steps_rejected, rejected);
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(M(i), direct.final(i));
}

TEST(DdbCompare, UntilSteadyWithFixedStepsStopsWhereThePlainRunFirstGetsThere) {
  // Fixed h: the states are those of the run without the flag, cut at the first whose r,
  // computed here, is within the tolerance.
  const fs::path plain = freshFolder("steady_plain"), cut = freshFolder("steady_cut");
  constexpr double kTolerance = 1e-3;
  ASSERT_EQ(runApp("--scenario B --method ddb-cay,rk4 --repeat 1 --out " + plain.string()), 0);
  ASSERT_EQ(runApp("--scenario B --method ddb-cay,rk4 --repeat 1 --until-steady 1e-3 --out " +
                   cut.string()),
            0);
  const Eigen::Vector3d inertia(1.0, 1.3, 0.5);
  for (const std::string method : {"ddb-cay", "rk4"}) {
    std::string header;
    const auto all = readCsv(plain / (method + ".csv"), &header);
    const auto rows = readCsv(cut / (method + ".csv"), &header);
    size_t first = 0;
    while (first < all.size() &&
           rigidBodyResidual(inertia, {all[first][1], all[first][2], all[first][3]}) > kTolerance) {
      ++first;
    }
    ASSERT_LT(first + 1, all.size()) << method << ": never within the tolerance";
    ASSERT_EQ(rows.size(), first + 1) << method;
    for (size_t k = 0; k < rows.size(); ++k) EXPECT_EQ(rows[k], all[k]) << method << " " << k;
    Json entry = readJson(cut / "summary.json")["methods"][method];
    EXPECT_EQ(entry["steady"], true);
    EXPECT_EQ(entry["steps"], static_cast<long>(first));
    EXPECT_EQ(entry["steps_rejected"], 0);
    EXPECT_EQ(entry["h_final"], 0.1);
    Json whole = readJson(plain / "summary.json")["methods"][method];
    EXPECT_EQ(whole["stop"], "step cap");
    EXPECT_EQ(whole["steady"], false);
  }
}

TEST(DdbCompare, SteadyStartsStopAtStepZero) {
  // The rigid body spinning about its stable axis e₂ (M × Ω = 0 exactly) and the fluid's
  // zonal flow (P and W diagonal, [P, W] = 0): steady before any step.
  for (const std::string arguments :
       {"--scenario B --omega0 0,1,0 --adaptive", "--scenario B --omega0 0,1,0",
        "--system zeitlin --n 8 --init zonal --adaptive",
        "--system zeitlin --n 8 --init zonal --method ddb-cay,rk4"}) {
    SCOPED_TRACE(arguments);
    const fs::path out = freshFolder("steady_start");
    ASSERT_EQ(runApp(arguments + " --until-steady 1e-12 --repeat 1 --out " + out.string()), 0);
    Json summary = readJson(out / "summary.json");
    ASSERT_FALSE(summary["methods"].empty());
    for (const auto& [name, entry] : summary["methods"].items()) {
      EXPECT_EQ(entry["steady"], true) << name;
      EXPECT_EQ(entry["steps"], 0) << name;
      EXPECT_EQ(entry["residual_final"], 0.0) << name;
      EXPECT_EQ(entry["err_final"], 0.0) << name;
      std::string header;
      EXPECT_EQ(readCsv(out / (name + ".csv"), &header).size(), 1u) << name;
    }
  }
}

TEST(DdbCompare, AdaptiveRunsOnlyTheMethodsThatKeepTheCasimirs) {
  const fs::path out = freshFolder("adaptive_methods");
  ASSERT_EQ(runApp("--scenario A --adaptive --t-end 5 --repeat 1 --out " + out.string()), 0);
  Json summary = readJson(out / "summary.json");
  EXPECT_NEAR(summary["t_end"].get<double>(), 5.0, 1e-15);
  for (const ddb::MethodInfo& info : ddb::kMethods) {
    if ((info.groups & ddb::kFixedSizeGroups) == 0) continue;
    const bool runs = summary["methods"].contains(info.name);
    if (!info.keeps_casimirs) {
      EXPECT_FALSE(runs) << info.name;
      continue;
    }
    if (!runs) continue;  // a method for other systems (the Lagrangian-only ones)
    const Json& entry = summary["methods"][info.name];
    EXPECT_EQ(entry["status"], "ok") << info.name;
    EXPECT_EQ(entry["stop"], "time cap") << info.name;
    EXPECT_NEAR(entry["t_final"].get<double>(), 5.0, 1e-12) << info.name;
    EXPECT_EQ(entry["energy_rises"], 0) << info.name;
    EXPECT_LT(entry["casimir_drift"].get<double>(), 1e-13) << info.name;
  }
  EXPECT_TRUE(summary["methods"].contains("sddb-exp"));
}

}  // namespace ddb_compare_tests
