// ddb-compare end to end on a short horizon: the files against the contract of
// docs/file-formats.md (columns, row count, JSON keys, finite values), the final state
// against the library called directly, and bad input (exit status 2, nothing written).
#include <ddb/integrators/method_registry.h>
#include <ddb/systems/rigid_body.h>
#include <gmock/gmock.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace {

namespace fs = std::filesystem;

int runApp(const std::string& arguments) {
  const std::string command =
      std::string(DDB_COMPARE_PATH) + " --quiet " + arguments + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

fs::path freshFolder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ddb_compare_test_" + name);
  fs::remove_all(dir);
  return dir;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::vector<double>> readCsv(const fs::path& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(DdbCompare, WritesContractFilesMatchingTheLibrary) {
  const fs::path out = freshFolder("contract");
  ASSERT_EQ(runApp("--scenario B --t-end 2 --h 0.1 --method ddb-cay,rk4 --out " + out.string()), 0);
  for (const std::string method : {"ddb-cay", "rk4"}) {
    std::string header;
    const auto rows = readCsv(out / (method + ".csv"), header);
    EXPECT_EQ(header, "t,m1,m2,m3,energy,casimir");
    ASSERT_EQ(rows.size(), 21u);  // t = 0, 0.1, ..., 2
    for (const auto& row : rows) {
      ASSERT_EQ(row.size(), 6u);
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
  const std::string summary = readFile(out / "summary.json");
  for (const std::string key :
       {"\"system\": \"rigid-body\"", "\"scenario\": \"B\"", "\"h\": ", "\"t_end\": 2",
        "\"methods\"", "\"ddb-cay\"", "\"rk4\"", "\"final\"", "\"err_final\"", "\"casimir_drift\"",
        "\"energy_final\"", "\"runtime_s\"", "\"steps\": 20"}) {
    EXPECT_THAT(summary, ::testing::HasSubstr(key));
  }
  EXPECT_THAT(summary, ::testing::Not(::testing::HasSubstr("null")));
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
    const auto rows = readCsv(out / "ddb-cay.csv", header);
    EXPECT_EQ(header, "t,m1,m2,m3,m4,m5,m6,energy,casimir1,casimir2");
    EXPECT_EQ(rows.size(), 11u);
    const std::string summary = readFile(out / "summary.json");
    EXPECT_THAT(summary, ::testing::HasSubstr("\"system\": \"" + system + "\""));
    for (const std::string method : {"ddb-cay", "ddb-exp", "ddb-exp-exact", "rk4", "lobatto3c"}) {
      EXPECT_THAT(summary, ::testing::HasSubstr("\"" + method + "\""));
    }
  }
}

TEST(DdbCompare, FailedSolveKeepsThePrefixAndExitsOne) {
  // ddb-exp-exact cannot solve its Legendre equation at h = 10 after 14 steps (see
  // Ddb.TooLargeStepThrowsTypedErrorAndKeepsPrefix): the valid prefix is written.
  const fs::path out = freshFolder("failure");
  ASSERT_EQ(runApp("--method ddb-exp-exact --h 10 --t-end 400 --repeat 1 --out " + out.string()),
            1);
  std::string header;
  const auto rows = readCsv(out / "ddb-exp-exact.csv", header);
  EXPECT_EQ(rows.size(), 15u);
  for (const auto& row : rows)
    for (double v : row) EXPECT_TRUE(std::isfinite(v));
  const std::string summary = readFile(out / "summary.json");
  EXPECT_THAT(summary, ::testing::HasSubstr("\"failure\": \"discrete Legendre equation did not "
                                            "converge at step 14"));
  EXPECT_THAT(summary, ::testing::HasSubstr("\"err_final\": null"));
}

TEST(DdbCompare, BadInputExitsTwoAndWritesNothing) {
  const std::vector<std::string> bad{
      "--system pendulum", "--scenario D",  "--method ddb-foo", "--h 0",
      "--h -0.1",          "--h nan",       "--t-end 0",        "--t-end 1e12 --h 1e-3",
      "--inertia 1,-1,2",  "--inertia 1,2", "--inertia 1,x,2",  "--omega0 0,0",
      "--alpha nan"};
  for (const auto& arguments : bad) {
    const fs::path out = freshFolder("bad");
    EXPECT_EQ(runApp(arguments + " --out " + out.string()), 2) << arguments;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << arguments;
  }
  EXPECT_EQ(runApp("--t-end 1 --out /proc/ddb-cannot-write"), 2);
}

}  // namespace
