// ddb-compare: compares integrators on the systems of its table (system_table.h): the
// paper's rigid-body scenarios (Section 5; docs/reference/conventions.md §3), the heavy top and
// Kirchhoff body, and the matrix groups' Manakov body and Zeitlin fluid
// (docs/reference/conventions.md §2), with the command line and files of
// docs/reference/command-lines-and-files.md. Exit status (apps/common/exit_status.h): 2 for bad
// input, checked in full before anything is written; 1 if a method failed (its valid prefix is
// still written and it is marked FAILED), a file could not be written or --plot failed
// (summary.json's figures_failure says why).
#include "common/cli.h"
#include "common/exit_status.h"
#include "common/logging.h"
#include "ddb_compare/options.h"
#include "ddb_compare/system_table.h"

namespace {

using namespace ddb;
using namespace ddb::compare;

int runCompare(int argc, char** argv) {
  CLI::App cli{"Compare integrators for double-bracket dissipation (paper, Section 5)", kApp};
  Options o;
  addOptions(cli, o);
  if (const auto status = app::parseCommandLine(cli, argc, argv)) return *status;
  app::setupLogging(o.log);

  const SystemRow& system = findSystem(o.system);
  rejectFlagsNotTaken(cli, system);
  return system.compare(cli, o);
}

}  // namespace

int main(int argc, char** argv) {
  return ddb::app::runMain(ddb::compare::kApp, runCompare, argc, argv);
}
