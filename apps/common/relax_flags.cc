#include "common/relax_flags.h"

#include "common/cli.h"
#include "common/format.h"

namespace ddb::app {

void addRelaxFlags(CLI::App& cli, RelaxFlags& flags, const std::string& until_steady_help,
                   const std::string& adaptive_help) {
  cli.add_option("--until-steady", flags.until_steady, until_steady_help);
  cli.add_flag("--adaptive", flags.adaptive, adaptive_help);
  cli.add_option("--adaptive-tol", flags.adaptive_tol,
                 "with --adaptive: tolerance on |dE/(h dE/dt) - 1| per step, in (0, 1) "
                 "(default " +
                     number(StepSizeControl().tolerance) + ")");
}

namespace {

/// `text` as `flag`'s number in (0, 1).
double openUnitInterval(const std::string& flag, const std::string& text) {
  const double value = parseNumber(flag, text, text);
  if (!(value > 0 && value < 1)) usageError(flag, text, "must be in (0, 1)");
  return value;
}

}  // namespace

void readRelaxFlags(const RelaxFlags& flags, RelaxOptions& options) {
  if (!flags.until_steady.empty()) {
    options.tolerance = openUnitInterval("--until-steady", flags.until_steady);
  }
  options.control.adaptive = flags.adaptive;
  if (!flags.adaptive_tol.empty()) {
    if (!flags.adaptive) usageError("--adaptive-tol", flags.adaptive_tol, "needs --adaptive");
    options.control.tolerance = openUnitInterval("--adaptive-tol", flags.adaptive_tol);
  }
}

}  // namespace ddb::app
