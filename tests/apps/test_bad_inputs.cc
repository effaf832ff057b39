// Every row of docs/reference/bad-inputs.md, run against the real apps: the table is the one
// source of the cases and of their messages. Each row must exit with status 2, print
// exactly one line on stderr that starts with "<app>: ", names the row's flag and
// contains the documented message, and create or change nothing: neither a new output
// folder, nor a file in an existing one, nor anything else in the scratch folder.
#include <gmock/gmock.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "app_test_support.h"

namespace bad_inputs_tests {

using namespace ddb::test;

struct Row {
  int line = 0;
  std::string app, arguments, flag, message;
};

/// The cells of a Markdown table row "| a | b |", with `\|` unescaped and the backticks
/// around a cell removed.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (line[i] == '|') {
      const auto begin = cell.find_first_not_of(' ');
      const auto end = cell.find_last_not_of(' ');
      cell = begin == std::string::npos ? "" : cell.substr(begin, end + 1 - begin);
      if (cell.size() >= 2 && cell.front() == '`' && cell.back() == '`') {
        cell = cell.substr(1, cell.size() - 2);
      }
      out.push_back(cell);
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return out;
}

/// The rows of the table whose header is "| app | arguments | flag | message |".
std::vector<Row> readTable(const fs::path& doc) {
  std::ifstream in(doc);
  std::vector<Row> rows;
  bool in_table = false;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.rfind("| app | arguments | flag | message |", 0) == 0) {
      in_table = true;
      continue;
    }
    if (!in_table || line.rfind("|---", 0) == 0) continue;
    if (line.empty() || line[0] != '|') break;
    const auto c = cells(line);
    EXPECT_EQ(c.size(), 4u) << doc << ":" << number;
    if (c.size() == 4) rows.push_back({number, c[0], c[1], c[2], c[3]});
  }
  return rows;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size()) {
    text.replace(at, from.size(), to);
  }
  return text;
}

/// Every file and folder below `root` with its content and modification time.
std::map<std::string, std::string> snapshot(const fs::path& root) {
  std::map<std::string, std::string> entries;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const auto stamp = std::to_string(entry.last_write_time().time_since_epoch().count());
    entries[entry.path().string()] =
        stamp + (entry.is_regular_file() ? " " + readFile(entry.path()) : " folder");
  }
  return entries;
}

TEST(BadInputs, EveryRowOfTheTableExitsTwoWithItsMessageAndWritesNothing) {
  const std::vector<Row> rows = readTable(DDB_BAD_INPUTS_DOC);
  ASSERT_GE(rows.size(), 40u) << "docs/reference/bad-inputs.md promises at least 40 rows";

  // The scratch folder {tmp} and its fixtures (docs/reference/bad-inputs.md lists them).
  const fs::path tmp = freshFolder("ddb_bad_inputs_", "scratch");
  fs::create_directories(tmp / "existing");
  std::ofstream(tmp / "existing" / "summary.json") << "{\"from\": \"an earlier run\"}\n";
  std::ofstream(tmp / "file") << "a regular file\n";
  // A valid 2x2 W (skew-Hermitian, traceless) with entries of 1e200.
  std::ofstream(tmp / "huge.csv") << "0,1e200,1e200,0\n-1e200,0,0,-1e200\n";
  // For --mu0-file: a real skew 2x2 M with entries of 1e200, a 3x3 that is symmetric, and
  // two rows of three numbers (neither N x N nor N x 2N).
  std::ofstream(tmp / "huge-m.csv") << "0,1e200\n-1e200,0\n";
  std::ofstream(tmp / "symmetric.csv") << "0,1,2\n1,0,3\n2,3,0\n";
  std::ofstream(tmp / "rect.csv") << "0,1,2\n-1,0,3\n";

  const std::map<std::string, std::string> programs{{"ddb-compare", DDB_COMPARE_PATH},
                                                    {"fluid-relax", FLUID_RELAX_PATH},
                                                    {"mhd-relax", MHD_RELAX_PATH}};
  RunEnvironment environment;
  environment.timeout_s = 20;  // a row that runs instead of failing must not hang ctest
  for (const Row& row : rows) {
    const std::string where = "docs/reference/bad-inputs.md:" + std::to_string(row.line) + ": " +
                              row.app + " " + row.arguments;
    ASSERT_EQ(programs.count(row.app), 1u) << where;
    const std::string arguments = replaceAll(row.arguments, "{tmp}", tmp.string());
    const std::string message = replaceAll(row.message, "{tmp}", tmp.string());
    // Without an --out of its own, a row runs once with a folder that does not exist and
    // once with one that holds an earlier file.
    std::vector<std::string> outs{""};
    if (arguments.find("--out") == std::string::npos) {
      outs = {" --out " + (tmp / "new").string(), " --out " + (tmp / "existing").string()};
    }
    for (const std::string& out : outs) {
      const auto before = snapshot(tmp);
      const AppResult r = runProgram(programs.at(row.app), arguments + out, environment);
      EXPECT_EQ(r.status, 2) << where << out << "\n" << r.output;
      EXPECT_EQ(std::count(r.error.begin(), r.error.end(), '\n'), 1) << where << "\n" << r.error;
      EXPECT_THAT(r.error, ::testing::StartsWith(row.app + ": ")) << where;
      EXPECT_THAT(r.error, ::testing::HasSubstr(row.flag)) << where;
      EXPECT_THAT(r.error, ::testing::HasSubstr(message)) << where;
      EXPECT_EQ(snapshot(tmp), before) << where << out << ": a file was created or changed";
    }
  }
  fs::remove_all(tmp);
}

// The library's thread count from the environment (core/thread_pool.h): refused by name,
// exit 2, before anything is written.
TEST(BadInputs, ABadDdbNumThreadsExitsTwoAndWritesNothing) {
  const fs::path tmp = freshFolder("ddb_bad_threads_", "scratch");
  const std::map<std::string, std::string> programs{{"ddb-compare", DDB_COMPARE_PATH},
                                                    {"fluid-relax", FLUID_RELAX_PATH},
                                                    {"mhd-relax", MHD_RELAX_PATH}};
  for (const auto& [app, path] : programs) {
    for (const std::string value : {"0", "-2", "two", "65", "3x"}) {
      RunEnvironment environment;
      environment.variables = {"DDB_NUM_THREADS=" + value};
      environment.timeout_s = 20;
      const AppResult r =
          runProgram(path, "--steps 10 --out " + (tmp / "run").string(), environment);
      EXPECT_EQ(r.status, 2) << app << " DDB_NUM_THREADS=" << value << "\n" << r.output;
      EXPECT_THAT(r.error, ::testing::StartsWith(app + ": ")) << r.error;
      EXPECT_THAT(r.error, ::testing::HasSubstr("DDB_NUM_THREADS")) << r.error;
      EXPECT_THAT(r.error, ::testing::HasSubstr(value)) << r.error;
      EXPECT_FALSE(fs::exists(tmp / "run")) << app << " DDB_NUM_THREADS=" << value;
    }
  }
  fs::remove_all(tmp);
}

}  // namespace bad_inputs_tests
