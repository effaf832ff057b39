// Output helpers for the apps: numbers at 17 significant digits, a minimal JSON
// writer, and atomic file writes (temporary name + rename), so that an
// interrupted run never leaves a half-written file under the final name.
#pragma once

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ddb::app {

inline std::string number(double v) {
  if (!std::isfinite(v)) return "null";  // JSON has no NaN/inf; CSV readers treat it as missing
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

/// CSV cells: non-finite values as "nan" (read back by every CSV reader).
inline std::string csvNumber(double v) { return std::isfinite(v) ? number(v) : "nan"; }

inline void writeFileAtomically(const std::filesystem::path& path, const std::string& content) {
  const std::filesystem::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
    out << content;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, path);
}

/// A JSON object built key by key (values are already-serialised JSON).
class JsonObject {
 public:
  JsonObject& add(const std::string& key, const std::string& raw_value) {
    entries_.push_back("\"" + key + "\": " + raw_value);
    return *this;
  }
  JsonObject& add(const std::string& key, double value) { return add(key, number(value)); }
  JsonObject& addString(const std::string& key, const std::string& value) {
    return add(key, quoted(value));
  }
  std::string str(int indent = 0) const {
    const std::string pad(indent + 2, ' ');
    std::string s = "{\n";
    for (size_t i = 0; i < entries_.size(); ++i) {
      s += pad + entries_[i] + (i + 1 < entries_.size() ? ",\n" : "\n");
    }
    return s + std::string(indent, ' ') + "}";
  }
  static std::string quoted(const std::string& v) {
    std::string s = "\"";
    for (char c : v) {
      if (c == '"' || c == '\\') s += '\\';
      s += (c == '\n') ? ' ' : c;
    }
    return s + "\"";
  }
  static std::string array(const std::vector<double>& values) {
    std::string s = "[";
    for (size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + number(values[i]);
    return s + "]";
  }

 private:
  std::vector<std::string> entries_;
};

}  // namespace ddb::app
