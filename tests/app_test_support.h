// Running an app end to end from a test: the app's exit status and output, its peak
// memory, fresh output folders, and the CSV files it writes (docs/file-formats.md).
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace ddb::test {

namespace fs = std::filesystem;

struct AppResult {
  int status = -1;      // exit status, -1 if killed
  std::string output;   // stdout and stderr together
  long max_rss_kb = 0;  // peak resident memory of the app alone
};

/// Runs `program` with whitespace-separated arguments, without a shell, so that wait4()
/// reports the app's own peak memory.
inline AppResult runProgram(const std::string& program, const std::string& arguments) {
  std::vector<std::string> words{program};
  std::stringstream ss(arguments);
  for (std::string word; ss >> word;) words.push_back(word);
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const fs::path log =
      fs::temp_directory_path() / ("ddb_app_test_output_" + std::to_string(::getpid()) + ".txt");
  const pid_t child = ::fork();
  if (child == 0) {
    std::FILE* out = std::fopen(log.c_str(), "w");
    if (out == nullptr) ::_exit(127);
    ::dup2(::fileno(out), STDOUT_FILENO);
    ::dup2(::fileno(out), STDERR_FILENO);
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
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  result.output = text.str();
  fs::remove(log);
  return result;
}

/// An empty (removed) folder under the system's temporary directory.
inline fs::path freshFolder(const std::string& prefix, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (prefix + name);
  fs::remove_all(dir);
  return dir;
}

inline std::string readFile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
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

}  // namespace ddb::test
