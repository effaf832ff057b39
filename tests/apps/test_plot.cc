// --plot without a shell (docs/reference/bad-inputs.md): the plotter's failure messages name what
// failed (a missing interpreter, the script's own error), and an output folder whose name
// a shell would read as commands reaches the script as one argument in both apps. A Newton
// search gets its figures; a figure that fails is exit status 1 and summary.json says so
// (docs/reference/command-lines-and-files.md, "Figures (`--plot`)").
#include <gmock/gmock.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app_test_support.h"
#include "common/plot.h"

namespace plot_tests {

using namespace ddb::test;
using ::testing::HasSubstr;
using ::testing::Not;

fs::path freshFolder(const std::string& name) { return ddb::test::freshFolder("plot_test_", name); }

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(Plot, MissingInterpreterIsNamed) {
  const fs::path dir = freshFolder("missing");
  fs::create_directories(dir);
  const std::string missing = (dir / "no-python3").string();
  const std::string failure = ddb::app::plotFailure(missing, "script.py", dir);
  EXPECT_THAT(failure, HasSubstr("cannot run the interpreter " + missing));
  EXPECT_THAT(failure, HasSubstr("No such file or directory"));
  EXPECT_THAT(failure, Not(HasSubstr("matplotlib")));

  const fs::path not_executable = dir / "python3";
  writeText(not_executable, "#!/bin/sh\n");
  ::chmod(not_executable.c_str(), 0644);
  EXPECT_THAT(ddb::app::plotFailure(not_executable.string(), "script.py", dir),
              HasSubstr("cannot run the interpreter " + not_executable.string()));
}

TEST(Plot, FailingScriptShowsTheEndOfItsStderr) {
  const fs::path dir = freshFolder("failing");
  fs::create_directories(dir);
  const fs::path script = dir / "fails.sh";
  writeText(script, "for i in $(seq 1 20); do echo \"line $i\" >&2; done\nexit 3\n");
  const std::string failure = ddb::app::plotFailure("/bin/sh", script.string(), dir);
  EXPECT_THAT(failure, HasSubstr(script.string() + " exited with status 3"));
  EXPECT_THAT(failure, HasSubstr("line 6\n"));
  EXPECT_THAT(failure, HasSubstr("line 20"));
  EXPECT_THAT(failure, Not(HasSubstr("line 5\n")));
}

TEST(Plot, ScriptGetsTheFolderAsOneArgument) {
  const fs::path dir = freshFolder("argument");
  fs::create_directories(dir);
  const fs::path script = dir / "echo.sh";
  writeText(script, "printf %s \"$1\" > \"$(dirname \"$0\")/argument.txt\"\n");
  const std::string out = "x'; \"$(touch y)\" `touch z`; '";
  EXPECT_EQ(ddb::app::plotFailure("/bin/sh", script.string(), out), "");
  EXPECT_EQ(readFile(dir / "argument.txt"), out);
}

struct App {
  const char* name;
  std::string program;
  std::vector<std::string> arguments;  // a short run
};

const std::vector<App>& apps() {
  static const std::vector<App> apps{
      {"ddb-compare",
       DDB_COMPARE_PATH,
       {"--quiet", "--t-end", "0.5", "--method", "ddb-cay,rk4", "--repeat", "1"}},
      {"fluid-relax", FLUID_RELAX_PATH, {"--quiet", "--n", "4", "--steps", "3"}}};
  return apps;
}

AppResult runWithPlot(const App& app, const fs::path& out) {
  std::vector<std::string> words = app.arguments;
  words.insert(words.end(), {"--plot", "--out", out.string()});
  return runProgram(app.program, words);
}

bool hasPng(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".png") return true;
  }
  return false;
}

TEST(Plot, OutputNamesAreNeverRunAsCommands) {
  for (const App& app : apps()) {
    const fs::path dir = freshFolder(std::string("injection_") + app.name);
    const fs::path sentinel = dir / "pwned";
    const std::string touch = "touch " + sentinel.string();
    for (const std::string& name : {"x'; " + touch + "; '", "x\"; " + touch + "; \"", "x; " + touch,
                                    "x$(" + touch + ")", "x`" + touch + "`"}) {
      const fs::path out = dir / name;
      const AppResult r = runWithPlot(app, out);
      EXPECT_EQ(r.status, 0) << app.name << " " << name << ": " << r.output;
      EXPECT_FALSE(fs::exists(sentinel)) << app.name << " " << name;
      EXPECT_FALSE(fs::exists("pwned")) << app.name << " " << name;
      EXPECT_TRUE(fs::is_directory(out) && hasPng(out)) << app.name << " " << name;
    }
  }
}

TEST(Plot, FolderWithSpacesAndAccentsGetsItsFigures) {
  for (const App& app : apps()) {
    const fs::path out = freshFolder(std::string("spaces_") + app.name) / "out dir é ü";
    const AppResult r = runWithPlot(app, out);
    ASSERT_EQ(r.status, 0) << app.name << ": " << r.output;
    EXPECT_TRUE(hasPng(out)) << app.name;
  }
}

TEST(Plot, ANewtonSearchGetsItsFigures) {
  // Its rows all have t = 0 and its summary h = null: the history is drawn against k.
  const fs::path out = freshFolder("newton");
  const AppResult r = runProgram(
      FLUID_RELAX_PATH, {"--quiet", "--n", "8", "--newton", "--until-steady", "1e-12", "--steps",
                         "6", "--every", "4", "--plot", "--out", out.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(out / "history.png"));
  EXPECT_TRUE(fs::is_regular_file(out / "vorticity_sphere.png"));
  EXPECT_EQ(readJson(out / "summary.json")["status"], "ok");
}

// With --h5 the spectrum too, from fluid.hdf5's energy_spectrum (where h5py is installed, as
// Debian's python3-h5py for the CI; without it the figure is left out, saying so).
TEST(Plot, AnH5RunGetsItsSpectrum) {
  const fs::path out = freshFolder("spectrum");
  const AppResult r =
      runProgram(FLUID_RELAX_PATH, {"--quiet", "--n", "8", "--steps", "6", "--every", "3", "--h5",
                                    "--plot", "--out", out.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  if (r.output.find("needs h5py") != std::string::npos) GTEST_SKIP() << r.output;
  EXPECT_TRUE(fs::is_regular_file(out / "spectrum.png")) << r.output;
  EXPECT_TRUE(fs::is_regular_file(out / "history.png"));
}

TEST(Plot, AFailedFigureIsExitStatusOneAndSummaryJsonSaysWhy) {
  // A matplotlib that cannot be imported, first on the interpreter's path.
  const fs::path dir = freshFolder("broken_matplotlib");
  fs::create_directories(dir / "site" / "matplotlib");
  writeText(dir / "site" / "matplotlib" / "__init__.py",
            "raise ImportError('this matplotlib is broken on purpose')\n");
  RunEnvironment environment;
  environment.variables = {"PYTHONPATH=" + (dir / "site").string()};
  for (const App& app : apps()) {
    SCOPED_TRACE(app.name);
    const fs::path out = dir / app.name;
    std::vector<std::string> words = app.arguments;
    words.insert(words.end(), {"--plot", "--out", out.string()});
    const AppResult r = runProgram(app.program, words, environment);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_THAT(r.output, HasSubstr("plotting failed"));
    const auto summary = readJson(out / "summary.json");
    EXPECT_THAT(summary["figures_failure"].get<std::string>(),
                HasSubstr("this matplotlib is broken on purpose"));
    // fluid-relax's run status says it; ddb-compare's methods keep theirs.
    if (summary.contains("status")) {
      EXPECT_EQ(summary["status"], "figures_failed");
    }
    EXPECT_FALSE(hasPng(out));
  }
}

}  // namespace plot_tests
