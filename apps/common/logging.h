// Logging for the apps: spdlog to stderr (stdout stays free for --help and --version),
// at info level by default, debug with --verbose, errors only with --quiet.
#pragma once

#include <CLI/CLI.hpp>

namespace ddb::app {

struct LogFlags {
  bool verbose = false;
  bool quiet = false;
};

/// Adds --verbose and --quiet (mutually exclusive) to `cli`.
void addLogFlags(CLI::App& cli, LogFlags& flags);

/// Sends spdlog's default logger to stderr at the level the flags ask for.
void setupLogging(const LogFlags& flags);

}  // namespace ddb::app
