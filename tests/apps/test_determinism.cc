// Two runs of each app with the same arguments write byte-identical files, apart from
// the runtime fields that docs/reference/command-lines-and-files.md lists ("Determinism"): those
// are masked here, by name, and nothing else is.
#include <gmock/gmock.h>
#include <locale.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "app_test_support.h"

namespace determinism_tests {

using namespace ddb::test;

/// The names of the files in `folder`.
std::set<std::string> fileNames(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

/// `json` with every "runtime_s" and "timed_runs" value, at any depth, replaced by "R".
void maskRuntimes(nlohmann::ordered_json& json) {
  if (!json.is_object()) return;
  for (auto& [key, value] : json.items()) {
    if (key == "runtime_s" || key == "timed_runs") {
      value = "R";
    } else {
      maskRuntimes(value);
    }
  }
}

/// `text` with the runtime fields of docs/reference/command-lines-and-files.md replaced by "R": in
/// summary.json "runtime_s" and "timed_runs" and every value of "runtime_table"; the
/// runtime column of runtime_table.md; the runtime_s column of error_vs_h.csv.
std::string withoutRuntimes(const std::string& name, const std::string& text) {
  if (name == "summary.json") {
    nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
    maskRuntimes(json);
    if (json.contains("runtime_table")) {
      for (auto& value : json["runtime_table"]) value = "R";
    }
    return json.dump(2);
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
    // The apps' lock of their folder is empty by design
    // (docs/reference/command-lines-and-files.md, "Run folders").
    if (name == "run.lock") {
      EXPECT_EQ(a + b, "");
      continue;
    }
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
  EXPECT_EQ(fileNames(first).size(), 11u);  // 7 trajectories, summary, table, sweep, run.lock
  expectSameFilesApartFromRuntimes(first, second);
}

TEST(Determinism, DdbCompareOnMatrixGroupsWritesTheSameFilesTwice) {
  // Every method of the table for matrix groups, and a sweep, on both matrix systems.
  for (const std::string system : {"manakov --j 1,1.5,2.5,3", "zeitlin --init l1"}) {
    const std::string arguments =
        "--quiet --system " + system + " --n 4 --t-end 1 --repeat 2 --sweep-h 0.05:0.1:2 --out ";
    const fs::path first = freshFolder("ddb_determinism_matrix_", "first");
    const fs::path second = freshFolder("ddb_determinism_matrix_", "second");
    ASSERT_EQ(runProgram(DDB_COMPARE_PATH, arguments + first.string()).status, 0) << system;
    ASSERT_EQ(runProgram(DDB_COMPARE_PATH, arguments + second.string()).status, 0) << system;
    expectSameFilesApartFromRuntimes(first, second);
  }
}

// A comma-decimal locale in the environment changes no byte of any file: numbers are
// formatted and parsed without the locale (apps/common/format.h, cli.h).
constexpr const char* kCommaLocale = "de_DE.UTF-8";

/// Skips the test (with the reason) if kCommaLocale is not installed.
bool commaLocaleInstalled() {
  const locale_t locale = ::newlocale(LC_ALL_MASK, kCommaLocale, static_cast<locale_t>(0));
  if (locale == static_cast<locale_t>(0)) return false;
  ::freelocale(locale);
  return true;
}

/// Runs `program` with `arguments` and --out twice, under LC_ALL=C and kCommaLocale,
/// and compares the files.
void expectSameFilesInBothLocales(const std::string& program, const std::string& arguments,
                                  const std::string& name) {
  const fs::path c = freshFolder("locale_c_", name);
  const fs::path comma = freshFolder("locale_comma_", name);
  RunEnvironment c_locale, comma_locale;
  c_locale.variables = {"LC_ALL=C"};
  comma_locale.variables = {std::string("LC_ALL=") + kCommaLocale};
  const AppResult r = runProgram(program, arguments + " --out " + comma.string(), comma_locale);
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_EQ(runProgram(program, arguments + " --out " + c.string(), c_locale).status, 0);
  expectSameFilesApartFromRuntimes(c, comma);
}

TEST(Determinism, DdbCompareIgnoresTheLocale) {
  if (!commaLocaleInstalled()) {
    GTEST_SKIP() << kCommaLocale << " is not installed (Debian: locales-all)";
  }
  // Decimal parameters on the command line, so that parsing is exercised too.
  expectSameFilesInBothLocales(DDB_COMPARE_PATH,
                               "--quiet --scenario B --t-end 1.5 --h 0.05 --alpha 0.25 "
                               "--repeat 1 --method ddb-cay,rk4",
                               "ddb_compare");
  expectSameFilesInBothLocales(DDB_COMPARE_PATH,
                               "--quiet --system heavy-top --t-end 1 --mgl 0.75 --repeat 1 "
                               "--method ddb-cay,reference",
                               "heavy_top");
}

TEST(Determinism, DdbCompareOnMatrixGroupsIgnoresTheLocale) {
  if (!commaLocaleInstalled()) {
    GTEST_SKIP() << kCommaLocale << " is not installed (Debian: locales-all)";
  }
  expectSameFilesInBothLocales(DDB_COMPARE_PATH,
                               "--quiet --system manakov --n 3 --j 1,1.5,2.5 --alpha 0.25 "
                               "--t-end 0.5 --repeat 1",
                               "manakov");
}

TEST(Determinism, FluidRelaxIgnoresTheLocale) {
  if (!commaLocaleInstalled()) {
    GTEST_SKIP() << kCommaLocale << " is not installed (Debian: locales-all)";
  }
  expectSameFilesInBothLocales(FLUID_RELAX_PATH, "--quiet --n 8 --steps 20 --alpha 0.75 --h 0.05",
                               "fluid_relax");
}

TEST(Determinism, FluidRelaxWritesTheSameFilesTwice) {
  const std::string arguments = "--quiet --n 12 --steps 30 --seed 4 --every 7 --out ";
  for (const std::string method : {"ddb-cay", "sddb-cay", "rk4"}) {
    const fs::path first = freshFolder("fluid_determinism_", "first");
    const fs::path second = freshFolder("fluid_determinism_", "second");
    const std::string args = "--method " + method + " " + arguments;
    ASSERT_EQ(runProgram(FLUID_RELAX_PATH, args + first.string()).status, 0);
    ASSERT_EQ(runProgram(FLUID_RELAX_PATH, args + second.string()).status, 0);
    EXPECT_EQ(fileNames(first).size(), 7u) << method;  // checkpoint.ddb and run.lock included
    expectSameFilesApartFromRuntimes(first, second);
  }
}

TEST(Determinism, MhdRelaxWritesTheSameFilesTwiceInEitherLocale) {
  // fluid.hdf5 holds its time of creation; its frames are compared in tests/python/test_mhd_h5.py.
  const std::string arguments = "--quiet --n 10 --steps 30 --every 7 --alpha 0.05 --h 0.02 --out ";
  const fs::path first = freshFolder("mhd_determinism_", "first");
  const fs::path second = freshFolder("mhd_determinism_", "second");
  RunEnvironment comma;
  if (commaLocaleInstalled()) comma.variables = {std::string("LC_ALL=") + kCommaLocale};
  ASSERT_EQ(runProgram(MHD_RELAX_PATH, arguments + first.string()).status, 0);
  ASSERT_EQ(runProgram(MHD_RELAX_PATH, arguments + second.string(), comma).status, 0);
  for (const fs::path& folder : {first, second}) {
    EXPECT_TRUE(fs::remove(folder / "fluid.hdf5"));
  }
  // history.csv, checkpoint.ddb, W_final.csv, theta_final.csv, summary.json, run.lock.
  EXPECT_EQ(fileNames(first).size(), 6u);
  expectSameFilesApartFromRuntimes(first, second);
}

}  // namespace determinism_tests
