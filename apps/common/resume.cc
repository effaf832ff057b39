#include "common/resume.h"

#include <spdlog/fmt/fmt.h>

#include <cmath>
#include <filesystem>

#include "common/cli.h"

namespace ddb::app {

RunFolderLock lockResumeFolder(const std::string& dir, const std::string& checkpoint_file) {
  const std::filesystem::path checkpoint = std::filesystem::path(dir) / checkpoint_file;
  RunFolderLock::refuseIfHeld("--resume", dir, dir);
  if (!std::filesystem::exists(std::filesystem::symlink_status(checkpoint))) {
    usageError("--resume", dir, "no checkpoint to resume from: " + checkpoint.string());
  }
  return RunFolderLock("--resume", dir, dir);
}

void resumeRelaxation(BinaryRecordReader& relaxation, const RelaxOptions& caps,
                      const std::string& dir, const std::string& checkpoint_file,
                      const std::function<RelaxState(BinaryRecordReader&)>& load) {
  RelaxState at;
  try {
    at = load(relaxation);
    relaxation.expectEnd();
  } catch (const CorruptRecord& corrupt) {
    usageError("--resume", dir,
               checkpoint_file + " is corrupt (" + corrupt.what() + "): refusing to use it");
  }
  const bool time_capped = std::isfinite(caps.t_end);
  if (!time_capped && at.k >= caps.max_steps) {
    usageError("--resume", dir,
               fmt::format("the run has taken {} steps, its cap {}; give a larger --steps "
                           "or --t-end",
                           at.k, caps.max_steps));
  }
  if (time_capped && at.t >= caps.t_end * (1 - 1e-12)) {
    usageError("--resume", dir,
               fmt::format("the run has reached t = {}, its cap; give a larger --t-end or "
                           "--steps",
                           at.t));
  }
}

void putRelaxCaps(BinaryRecordWriter& out, const RelaxOptions& relax) {
  out.put(relax.tolerance);
  out.put(relax.max_steps);
  out.put(relax.t_end);
  out.put(relax.control.adaptive);
  out.put(relax.control.tolerance);
}

void getRelaxCaps(BinaryRecordReader& in, RelaxOptions& relax) {
  in.get(relax.tolerance);
  in.get(relax.max_steps);
  in.get(relax.t_end);
  in.get(relax.control.adaptive);
  in.get(relax.control.tolerance);
}

}  // namespace ddb::app
