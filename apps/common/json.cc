#include "common/json.h"

#include "common/atomic_file.h"

namespace ddb::app {

void writeJsonFile(const std::filesystem::path& path, const Json& json) {
  writeFileAtomically(path, json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
}

}  // namespace ddb::app
