#include "common/logging.h"

#include <ddb/core/openblas_kernels.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <string>

namespace ddb::app {

void addLogFlags(CLI::App& cli, LogFlags& flags) {
  auto* verbose = cli.add_flag("--verbose", flags.verbose, "debug logging");
  cli.add_flag("--quiet", flags.quiet, "errors only, no progress line")->excludes(verbose);
}

void setupLogging(const LogFlags& flags) {
  auto logger = spdlog::stderr_color_mt("stderr");
  logger->set_pattern("[%H:%M:%S] %^%l%$: %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(flags.quiet     ? spdlog::level::err
                    : flags.verbose ? spdlog::level::debug
                                    : spdlog::level::info);
}

void warnAboutSlowBlasKernels() {
  if (const std::string advice = openblasKernelAdvice(); !advice.empty()) {
    spdlog::warn("{}", advice);
  }
}

}  // namespace ddb::app
