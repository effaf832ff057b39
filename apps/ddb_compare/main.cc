// ddb-compare: compares integrators on the paper's rigid-body scenarios (Section 5;
// docs/conventions.md §3), on the heavy top and Kirchhoff body, and on the matrix groups'
// Manakov body and Zeitlin fluid (docs/conventions.md §2), with the command line
// and files of docs/file-formats.md. Exit status (apps/common/exit_status.h): 2 for bad
// input, checked in full before anything is written; 1 if a method failed (its valid
// prefix is still written and it is marked FAILED) or a file could not be written.
#include <ddb/core/errors.h>

#include <algorithm>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/logging.h"
#include "common/plot.h"
#include "ddb_compare/comparison.h"
#include "ddb_compare/matrix_problems.h"
#include "ddb_compare/options.h"
#include "ddb_compare/problems.h"

namespace {

using namespace ddb;
using namespace ddb::compare;

/// Library checks of the problem's data (InvalidArgument) are bad input too.
template <class F>
auto asUsageError(F&& make) {
  try {
    return make();
  } catch (const InvalidArgument& e) {
    throw app::UsageError(e.what());
  }
}

/// Every check of the input, in the order the messages name them, then the comparison.
template <class MakeProblem>
int checkAndCompare(const Options& o, const MakeProblem& make) {
  const auto problem = make(o);
  const Settings settings = commonSettings(o, problem.t_end);
  requireResolvable(o, problem, make);
  return runComparison(o, settings, problem);
}

int runCompare(int argc, char** argv) {
  CLI::App cli{"Compare integrators for double-bracket dissipation (paper, Section 5)", kApp};
  Options o;
  addOptions(cli, o);
  if (const auto status = app::parseCommandLine(cli, argc, argv)) return *status;
  app::setupLogging(o.log);

  app::requireChoice("--system", o.system, app::namesOf(systemDescriptions()));
  const auto rigidBody = [&](const Options& options) {
    return asUsageError([&] { return rigidBodyProblem(cli, options); });
  };
  const auto se3 = [&](const Options& options) {
    return asUsageError([&] { return se3Problem(cli, options); });
  };
  const auto manakov = [&](const Options& options) {
    return asUsageError([&] { return manakovProblem(cli, options); });
  };
  const auto zeitlin = [&](const Options& options) {
    return asUsageError([&] { return zeitlinProblem(cli, options); });
  };
  int status = 0;
  if (o.system == "rigid-body") {
    status = checkAndCompare(o, rigidBody);
  } else if (o.system == "manakov") {
    status = checkAndCompare(o, manakov);
  } else if (o.system == "zeitlin") {
    status = checkAndCompare(o, zeitlin);
  } else {
    status = checkAndCompare(o, se3);
  }
  if (o.plot) status = std::max(status, app::runPlotScript(DDB_PLOT_SCRIPT, o.out));
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  return ddb::app::runMain(ddb::compare::kApp, runCompare, argc, argv);
}
