// Figures: the apps render PNGs by running a matplotlib script of scripts/ on their
// output folder (docs/file-formats.md, --plot), with the interpreter CMake found.
#pragma once

#include <filesystem>
#include <string>

namespace ddb::app {

/// Runs `python3 script out`; returns kExitOk, or logs the failure and returns kExitFailed.
int runPlotScript(const std::string& script, const std::filesystem::path& out);

}  // namespace ddb::app
