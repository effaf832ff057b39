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

/// plotFailure() with pythonInterpreter(); returns kExitOk, or logs the failure and
/// returns kExitFailed.
int runPlotScript(const std::string& script, const std::filesystem::path& out);

/// runPlotScript() with the arguments `script arguments...` (scripts/animate_fluid.py's
/// input file and output video).
int runPlotScript(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace ddb::app
