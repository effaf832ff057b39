#include "common/json.h"

#include <cmath>
#include <cstdio>

#include "common/format.h"

namespace ddb::app {

JsonObject& JsonObject::add(const std::string& key, const std::string& raw_value) {
  entries_.push_back(quoted(key) + ": " + raw_value);
  return *this;
}

JsonObject& JsonObject::add(const std::string& key, double value) {
  return add(key, number(value));
}

JsonObject& JsonObject::add(const std::string& key, long value) {
  return add(key, std::to_string(value));
}

JsonObject& JsonObject::addString(const std::string& key, const std::string& value) {
  return add(key, quoted(value));
}

std::string JsonObject::str(int indent) const {
  const std::string pad(indent + 2, ' ');
  std::string s = "{\n";
  for (size_t i = 0; i < entries_.size(); ++i) {
    s += pad + entries_[i] + (i + 1 < entries_.size() ? ",\n" : "\n");
  }
  return s + std::string(indent, ' ') + "}";
}

std::string JsonObject::number(double v) { return std::isfinite(v) ? app::number(v) : "null"; }

std::string JsonObject::quoted(const std::string& v) {
  std::string s = "\"";
  for (const char c : v) {
    if (c == '"' || c == '\\') {
      s += '\\';
      s += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
      s += escaped;
    } else {
      s += c;
    }
  }
  return s + "\"";
}

std::string JsonObject::array(const std::vector<double>& values) {
  std::string s = "[";
  for (size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + number(values[i]);
  return s + "]";
}

}  // namespace ddb::app
