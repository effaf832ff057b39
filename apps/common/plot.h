// Figures: the apps render PNGs by running a matplotlib script of scripts/ on their
// output folder (docs/reference/command-lines-and-files.md, --plot), with the interpreter CMake
// found. The script runs from an argument vector, never through a shell, so that no output folder
// name is ever read as a command (docs/reference/bad-inputs.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ddb::app {

/// The python3 CMake found (DDB_PYTHON3): Debian's, which has matplotlib and scipy.
std::string pythonInterpreter();

/// Runs `interpreter script out` as a child process (posix_spawnp, no shell) and waits
/// for it. Returns "" if it exited with status 0, else what failed: the interpreter
/// that could not be started (its path and why), or the script's exit status or signal
/// with the last lines of its stderr.
std::string plotFailure(const std::string& interpreter, const std::string& script,
                        const std::filesystem::path& out);

/// plotFailure() with the arguments `interpreter script arguments...`.
std::string plotFailure(const std::string& interpreter, const std::string& script,
                        const std::vector<std::string>& arguments);

/// plotFailure() with pythonInterpreter(); logs a failure and returns it ("" if none).
std::string runPlotScript(const std::string& script, const std::filesystem::path& out);

/// runPlotScript() with the arguments `script arguments...` (scripts/animate_fluid.py's
/// input file and output video).
std::string runPlotScript(const std::string& script, const std::vector<std::string>& arguments);

/// A run whose figures failed (`failure`, not empty) after its files were written: its
/// summary.json (`summary`) says so, so that it never reads "ok" beside exit status 1
/// (docs/reference/command-lines-and-files.md, "Figures (`--plot`)"): "figures_failure" is
/// the failure, and a "status" of "ok" becomes "figures_failed". Returns kExitFailed.
int recordFiguresFailure(const std::filesystem::path& summary, const std::string& failure);

}  // namespace ddb::app
