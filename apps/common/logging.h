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

/// Warns when OpenBLAS runs kernels below what the CPU supports, naming OPENBLAS_CORETYPE's
/// value (core/openblas_kernels.h). Called once as a run starts, after its input was accepted,
/// so that a refusal stays one line.
void warnAboutSlowBlasKernels();

}  // namespace ddb::app
