#include "fluid_relax/run_files.h"

#include <filesystem>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/journal_file.h"
#include "fluid_relax/fluid_h5.h"
#include "fluid_relax/outputs.h"

namespace ddb::fluid {

const app::RunFiles& runFiles() {
  static const app::RunFiles files{{kHistoryCsv, app::JournalFile::partialOf(kHistoryCsv).string(),
                                    kCheckpointFile, "W_final.csv", "omega_initial.csv",
                                    "omega_final.csv", "summary.json", kFluidH5, "fluid.mp4",
                                    // scripts/animate_fluid.py's and plot_fluid.py's
                                    "fluid.partial.mp4", "history.png", "vorticity_sphere.png",
                                    "history.png.tmp.png", "vorticity_sphere.png.tmp.png"}};
  return files;
}

void checkResumeFolder(const std::string& dir, Checkpoint& c) {
  const std::filesystem::path folder(dir);
  const std::filesystem::path history = app::JournalFile::resumeFileOf(folder / kHistoryCsv);
  const std::uint64_t size = app::requireRegularFile("--resume", dir, history);
  const std::uint64_t recorded = c.files.history_bytes;
  if (size < recorded) {
    app::usageError("--resume", dir,
                    history.string() + " has " + std::to_string(size) + " bytes, fewer than the " +
                        std::to_string(recorded) +
                        " its checkpoint recorded: it is not the history its checkpoint "
                        "continues (restore it to resume)");
  }
  const std::uint64_t digest = app::digestOfPrefix("--resume", dir, history, recorded);
  if (c.files.history_digest && *c.files.history_digest != digest) {
    app::usageError("--resume", dir,
                    history.string() + " is not the history its checkpoint continues (its first " +
                        std::to_string(recorded) +
                        " bytes are not those the run wrote): another run's, or altered");
  }
  c.files.history_digest = digest;

  const std::filesystem::path h5 = folder / kFluidH5;
  if (c.options.h5 || c.options.animate) {
    app::requireRegularFile("--resume", dir, h5);
    try {
      // ħ is not compared (it follows from N), nor the version and time of creation.
      FluidH5::checkResumable(h5, h5Attributes(c.options, c.settings, 0.0), c.files.h5_frames,
                              c.files.field_diagnostics);
    } catch (const app::IoError& error) {
      app::usageError("--resume", dir, std::string(error.what()) + ": refusing to resume into it");
    }
  } else if (std::filesystem::exists(std::filesystem::symlink_status(h5))) {
    app::usageError("--resume", dir,
                    h5.string() +
                        " is in the folder, but the checkpoint's run writes none (it "
                        "ran without --h5): it is another run's; move it away to resume");
  }
}

}  // namespace ddb::fluid
