// summary.json (docs/reference/command-lines-and-files.md) through nlohmann-json: ordered_json
// keeps the keys in the order the apps add them, and a non-finite double is dumped as null (JSON
// has no NaN or infinity; a failed method's err_final, for instance).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

namespace ddb::app {

using Json = nlohmann::ordered_json;

/// The entries of `v`, as a JSON array of numbers.
inline Json jsonArray(const Eigen::Ref<const Eigen::VectorXd>& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

/// Writes `json`, indented by 2, and a newline to `path` through AtomicFile; a string
/// that is not UTF-8 (a file name, a message quoting one) gets U+FFFD for its bad bytes
/// instead of failing the run.
void writeJsonFile(const std::filesystem::path& path, const Json& json);

/// The JSON document in `path` (a summary.json an app wrote); an IoError naming the file if it
/// cannot be read or parsed.
Json readJsonFile(const std::filesystem::path& path);

}  // namespace ddb::app
