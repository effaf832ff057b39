// Two runs of each app with the same arguments write byte-identical files, apart from
// the runtime fields that docs/file-formats.md lists ("Determinism"): those are masked
// here, by name, and nothing else is.
#include <gmock/gmock.h>

#include <regex>
#include <set>
#include <string>

#include "app_test_support.h"

namespace {

using namespace ddb::test;

/// The names of the files in `folder`.
std::set<std::string> fileNames(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

/// `text` with the runtime fields of docs/file-formats.md replaced by "R": in
/// summary.json "runtime_s" and "timed_runs" and every value of "runtime_table"; the
/// runtime column of runtime_table.md; the runtime_s column of error_vs_h.csv.
std::string withoutRuntimes(const std::string& name, const std::string& text) {
  if (name == "summary.json") {
    std::string masked =
        std::regex_replace(text, std::regex("(\"(runtime_s|timed_runs)\": )[^,\n]+"), "$1R");
    const std::size_t table = masked.find("\"runtime_table\": {");
    if (table == std::string::npos) return masked;
    const std::size_t end = masked.find('}', table);
    return masked.substr(0, table) +
           std::regex_replace(masked.substr(table, end - table),
                              std::regex("(\"[a-z0-9-]+\": )[^,\n]+"), "$1R") +
           masked.substr(end);
  }
  if (name == "runtime_table.md") {
    return std::regex_replace(text, std::regex("(\n\\| [a-z0-9-]+ \\| )[^|]+"), "$1R ");
  }
  if (name == "error_vs_h.csv") return std::regex_replace(text, std::regex(",[^,\n]+\n"), ",R\n");
  return text;
}

void expectSameFilesApartFromRuntimes(const fs::path& first, const fs::path& second) {
  ASSERT_EQ(fileNames(first), fileNames(second));
  for (const std::string& name : fileNames(first)) {
    const std::string a = readFile(first / name), b = readFile(second / name);
    ASSERT_FALSE(a.empty()) << name;
    EXPECT_EQ(withoutRuntimes(name, a), withoutRuntimes(name, b)) << name;
  }
}

TEST(Determinism, DdbCompareWritesTheSameFilesTwice) {
  // Every kind of method (DDB, symmetric, composed, explicit, implicit RK, adaptive) and
  // a sweep, so that every file ddb-compare writes is compared.
  const std::string arguments =
      "--quiet --scenario B --t-end 2 --repeat 2 --sweep-h 0.05:0.1:2 "
      "--method ddb-cay,ddb-exp,sddb-cay,ddb4-exp,rk4,lobatto3c,reference --out ";
  const fs::path first = freshFolder("ddb_determinism_", "first");
  const fs::path second = freshFolder("ddb_determinism_", "second");
  ASSERT_EQ(runProgram(DDB_COMPARE_PATH, arguments + first.string()).status, 0);
  ASSERT_EQ(runProgram(DDB_COMPARE_PATH, arguments + second.string()).status, 0);
  EXPECT_EQ(fileNames(first).size(), 10u);  // 7 trajectories, summary, table, sweep
  expectSameFilesApartFromRuntimes(first, second);
}

TEST(Determinism, FluidRelaxWritesTheSameFilesTwice) {
  const std::string arguments = "--quiet --n 12 --steps 30 --seed 4 --every 7 --out ";
  for (const std::string method : {"ddb-cay", "sddb-cay", "rk4"}) {
    const fs::path first = freshFolder("fluid_determinism_", "first");
    const fs::path second = freshFolder("fluid_determinism_", "second");
    const std::string args = "--method " + method + " " + arguments;
    ASSERT_EQ(runProgram(FLUID_RELAX_PATH, args + first.string()).status, 0);
    ASSERT_EQ(runProgram(FLUID_RELAX_PATH, args + second.string()).status, 0);
    EXPECT_EQ(fileNames(first).size(), 5u) << method;
    expectSameFilesApartFromRuntimes(first, second);
  }
}

}  // namespace
