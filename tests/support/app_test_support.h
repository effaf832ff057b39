// Running an app end to end from a test: the app's exit status and output, its peak
// memory, fresh output folders, and the CSV files it writes
// (docs/reference/command-lines-and-files.md).
#pragma once

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Core>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace ddb::test {

namespace fs = std::filesystem;

inline std::string readFile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct AppResult {
  int status = -1;      // exit status, -1 if killed (e.g. by the timeout)
  std::string output;   // stdout, then stderr
  std::string error;    // stderr alone
  long max_rss_kb = 0;  // peak resident memory of the app alone
};

/// How runProgram() starts the app beyond its arguments.
struct RunEnvironment {
  std::vector<std::string> variables;  // "NAME=value", added to the test's environment
  unsigned timeout_s = 0;              // kill the app (SIGALRM) after this; 0: never
};

#ifdef DDB_MPI_TEST_ENVIRONMENT
/// The environment of the apps started under mpiexec: the MPI tests' own (ddb_mpi_test_env,
/// tests/mpi/tests.cmake, which says why each variable), given as DDB_MPI_TEST_ENVIRONMENT to the
/// test programs that start mpiexec, so that one list serves ctest's runs and the tests' own.
inline const std::vector<std::string> kMpiVariables = [] {
  std::vector<std::string> variables;
  std::stringstream ss(DDB_MPI_TEST_ENVIRONMENT);
  for (std::string variable; ss >> variable;) variables.push_back(variable);
  return variables;
}();
#endif

/// Runs `program` with the arguments `words`, without a shell, so that wait4() reports
/// the app's own peak memory and an argument reaches the app as it is (spaces, quotes).
inline AppResult runProgram(const std::string& program, std::vector<std::string> words,
                            const RunEnvironment& environment = {}) {
  words.insert(words.begin(), program);
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string stem = "ddb_app_test_" + std::to_string(::getpid());
  const fs::path out_log = fs::temp_directory_path() / (stem + "_stdout.txt");
  const fs::path err_log = fs::temp_directory_path() / (stem + "_stderr.txt");
  const pid_t child = ::fork();
  if (child == 0) {
    std::FILE* out = std::fopen(out_log.c_str(), "w");
    std::FILE* err = std::fopen(err_log.c_str(), "w");
    if (out == nullptr || err == nullptr) ::_exit(127);
    ::dup2(::fileno(out), STDOUT_FILENO);
    ::dup2(::fileno(err), STDERR_FILENO);
    for (const auto& variable : environment.variables) ::putenv(strdup(variable.c_str()));
    // An alarm survives execv: a hanging app is killed instead of hanging the test.
    if (environment.timeout_s > 0) ::alarm(environment.timeout_s);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  AppResult result;
  int status = 0;
  rusage usage{};
  if (child > 0 && ::wait4(child, &status, 0, &usage) == child) {
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.max_rss_kb = usage.ru_maxrss;
  }
  result.error = readFile(err_log);
  result.output = readFile(out_log) + result.error;
  fs::remove(out_log);
  fs::remove(err_log);
  return result;
}

/// runProgram() with whitespace-separated arguments.
inline AppResult runProgram(const std::string& program, const std::string& arguments,
                            const RunEnvironment& environment = {}) {
  std::vector<std::string> words;
  std::stringstream ss(arguments);
  for (std::string word; ss >> word;) words.push_back(word);
  return runProgram(program, std::move(words), environment);
}

/// Starts `words` (the program first) in the background with the variables of
/// `environment` added, stderr discarded and a SIGALRM after 120 s; waits until
/// `out`/checkpoint.ddb exists (at most 60 s) and returns the child's pid, for the caller
/// to signal it (or its children) and waitForExit() it.
inline pid_t startUntilCheckpoint(std::vector<std::string> words, const fs::path& out,
                                  const std::vector<std::string>& environment = {}) {
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    for (const std::string& variable : environment) {
      const auto equals = variable.find('=');
      ::setenv(variable.substr(0, equals).c_str(), variable.substr(equals + 1).c_str(), 1);
    }
    std::FILE* null = std::fopen("/dev/null", "w");
    if (null != nullptr) ::dup2(::fileno(null), STDERR_FILENO);
    ::alarm(120);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(out / "checkpoint.ddb") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return child;
}

/// The exit status of `child` (-signal if a signal killed it), once it has ended.
inline int waitForExit(pid_t child) {
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

/// The JSON file at `path`, parsed (summary.json keeps its key order: ordered_json).
inline nlohmann::ordered_json readJson(const fs::path& path) {
  return nlohmann::ordered_json::parse(readFile(path));
}

/// Removes the folders freshFolder() handed out once the test that asked for them has ended
/// without a failure, or, for those a suite's SetUpTestSuite asked for, once the whole suite has;
/// a failure's folders stay, named in the test's output, to be looked at. Without it each ctest run
/// left about 1 200 folders under the temporary directory.
class FreshFolderCleanup : public ::testing::EmptyTestEventListener {
 public:
  static FreshFolderCleanup& instance() {
    // Owned by GoogleTest's listener list, which deletes it when the program ends.
    static auto* const cleanup = [] {
      auto* listener = new FreshFolderCleanup;
      ::testing::UnitTest::GetInstance()->listeners().Append(listener);
      return listener;
    }();
    return *cleanup;
  }
  void add(const fs::path& dir) {
    const bool in_test = ::testing::UnitTest::GetInstance()->current_test_info() != nullptr;
    (in_test ? test_folders_ : suite_folders_).push_back(dir);
  }

 private:
  void OnTestEnd(const ::testing::TestInfo& info) override {
    settle(test_folders_, !info.result()->Failed());
  }
  void OnTestSuiteEnd(const ::testing::TestSuite& suite) override {
    settle(suite_folders_, !suite.Failed());
  }
  static void settle(std::vector<fs::path>& folders, bool passed) {
    for (const fs::path& dir : folders) {
      std::error_code ignored;
      if (passed) {
        fs::remove_all(dir, ignored);
      } else if (fs::exists(dir, ignored)) {
        std::printf("[ kept     ] %s\n", dir.c_str());
      }
    }
    folders.clear();
  }
  std::vector<fs::path> test_folders_, suite_folders_;
};

/// An empty (removed) folder under the system's temporary directory, named for this process
/// too, so that two suites run at once (ctest -j, two checkouts) never share one. It is removed
/// again once its test has passed (FreshFolderCleanup).
inline fs::path freshFolder(const std::string& prefix, const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / (prefix + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  FreshFolderCleanup::instance().add(dir);
  return dir;
}

/// The numeric rows of a CSV file; its header line into *header unless null.
inline std::vector<std::vector<double>> readCsv(const fs::path& path, std::string* header) {
  std::ifstream in(path);
  std::string line;
  if (header != nullptr) std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

/// A matrix from --init-file's CSV layout (W_final.csv: row j is Re W[j, :] then Im W[j, :]).
inline Eigen::MatrixXcd readMatrix(const fs::path& path) {
  const auto rows = readCsv(path, nullptr);
  const auto n = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXcd W(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    if (static_cast<Eigen::Index>(rows[j].size()) != 2 * n) {
      ADD_FAILURE() << path << " row " << j << " has " << rows[j].size() << " numbers, not 2N";
      return W;
    }
    for (Eigen::Index k = 0; k < n; ++k) W(j, k) = {rows[j][k], rows[j][n + k]};
  }
  return W;
}

/// W in --init-file's CSV layout (row j: Re W[j, :] then Im W[j, :]), every digit kept.
inline void writeMatrix(const fs::path& path, const Eigen::MatrixXcd& W) {
  std::ofstream out(path);
  out.precision(17);
  for (Eigen::Index j = 0; j < W.rows(); ++j) {
    for (Eigen::Index k = 0; k < W.cols(); ++k) out << W(j, k).real() << ",";
    for (Eigen::Index k = 0; k < W.cols(); ++k) {
      out << W(j, k).imag() << (k + 1 < W.cols() ? "," : "\n");
    }
  }
}

}  // namespace ddb::test
