#include "common/number_csv.h"

#include <filesystem>
#include <fstream>

#include "common/cli.h"

namespace ddb::app {

namespace {

/// The text of a cell with surrounding blanks removed.
std::string trimmed(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t") + 1 - begin);
}

}  // namespace

std::vector<std::vector<double>> readNumberCsv(const std::string& flag, const std::string& path,
                                               std::size_t max_rows, const std::string& limit) {
  const auto bad = [&](const std::string& why) { usageError(flag, path, why); };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) bad("not a readable file");
  std::ifstream in(path);
  if (!in) bad("cannot be opened");
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trimmed(line).empty()) continue;
    if (rows.size() == max_rows) {
      bad("more than " + std::to_string(max_rows) + " rows (" + limit + ")");
    }
    rows.emplace_back();
    for (const auto& cell : split(line))
      rows.back().push_back(parseNumber(flag, path, trimmed(cell)));
  }
  if (in.bad()) bad("read error");
  return rows;
}

}  // namespace ddb::app
