#include "common/json.h"

#include <fstream>

#include "common/atomic_file.h"
#include "common/exit_status.h"

namespace ddb::app {

void writeJsonFile(const std::filesystem::path& path, const Json& json) {
  writeFileAtomically(path, json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
}

Json readJsonFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot read " + path.string());
  try {
    return Json::parse(in);
  } catch (const Json::exception& e) {
    throw IoError("cannot parse " + path.string() + ": " + e.what());
  }
}

}  // namespace ddb::app
