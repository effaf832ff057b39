// fluid-relax: relaxes Zeitlin's SU(N) fluid on the sphere (docs/reference/conventions.md §2) with
// double-bracket dissipation towards a steady flow, with the command line and files of
// docs/reference/command-lines-and-files.md ("fluid-relax"). Exit status
// (apps/common/exit_status.h): 2 for bad input, checked in full before anything is written; 1 if a
// step failed (history.csv keeps every state before it) or a file could not be written; 130/143 if
// SIGINT/SIGTERM stopped it (after its step, with outputs and a checkpoint: "Checkpoints" there).
// The run is fluid_relax/fluid_run.h's, on the row of the device table (fluid_relax/device.h)
// that --device names: this process's memory, or one GPU's (docs/guide/gpu.md).
#include <ddb/groups/sun.h>

#include <optional>
#include <string>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/resume.h"
#include "common/run_folder.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/device.h"
#include "fluid_relax/input.h"
#include "fluid_relax/options.h"
#include "fluid_relax/outputs.h"
#include "fluid_relax/run_files.h"

namespace {

using namespace ddb;
using namespace ddb::fluid;

int runRelax(int argc, char** argv) {
  CLI::App cli{"Relax Zeitlin's SU(N) fluid on the sphere with double-bracket dissipation", kApp};
  Options o;
  addOptions(cli, o, kMaxN);
  cli.add_option(
         "--device", o.device,
         "where the states live: cpu, or cuda (one GPU, N <= " + std::to_string(SUN::kMaxN) +
             ", every --method and --newton; docs/guide/gpu.md); a checkpoint resumes "
             "on either")
      ->capture_default_str();
  if (const auto status = app::parseCommandLine(cli, argc, argv)) return *status;
  app::setupLogging(o.log);
  const Device& device = deviceOf(o.device);
  std::optional<app::RunFolderLock> lock;
  if (!o.resume.empty()) {
    // The lock first: the checkpoint and the files are read as their one writer left them.
    lock.emplace(app::lockResumeFolder(o.resume, kCheckpointFile));
    Checkpoint c = readCheckpoint(o.resume);
    resumeSettings(cli, o, c);
    requireRunsOn(device, c.settings.W0.rows());
    checkResumeFolder(o.resume, c);
    const int status = device.relax(c.options, c.settings, c.given, &c, lock);
    return makeFigures(c.options, c.settings.out, status, DDB_PLOT_SCRIPT, DDB_ANIMATE_SCRIPT);
  }
  const Settings s = settings(cli, o, device.max_n);
  requireRunsOn(device, s.W0.rows());
  const int status = device.relax(o, s, givenFlags(cli), nullptr, lock);
  return makeFigures(o, s.out, status, DDB_PLOT_SCRIPT, DDB_ANIMATE_SCRIPT);
}

}  // namespace

int main(int argc, char** argv) {
  return ddb::app::runMain(ddb::fluid::kApp, runRelax, argc, argv);
}
