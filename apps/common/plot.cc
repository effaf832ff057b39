#include "common/plot.h"

#include <spdlog/spdlog.h>

#include <cstdlib>

#include "common/exit_status.h"

namespace ddb::app {

int runPlotScript(const std::string& script, const std::filesystem::path& out) {
  const std::string command =
      "'" + std::string(DDB_PYTHON3) + "' '" + script + "' '" + out.string() + "'";
  spdlog::info("plotting: {}", command);
  const int status = std::system(command.c_str());
  if (status != 0) spdlog::error("plotting failed (python3 with matplotlib is needed)");
  return status == 0 ? kExitOk : kExitFailed;
}

}  // namespace ddb::app
