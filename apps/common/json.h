// A minimal JSON writer for summary.json (docs/file-formats.md): an object built key by
// key, values already serialised. JSON has no NaN or infinity, so a non-finite number
// is written as null (a failed method's err_final, for instance).
#pragma once

#include <string>
#include <vector>

namespace ddb::app {

class JsonObject {
 public:
  /// Adds `"key": raw_value`; raw_value must already be JSON.
  JsonObject& add(const std::string& key, const std::string& raw_value);
  JsonObject& add(const std::string& key, double value);
  JsonObject& add(const std::string& key, long value);
  JsonObject& addString(const std::string& key, const std::string& value);
  /// The object, nested `indent` spaces deep.
  std::string str(int indent = 0) const;

  static std::string number(double v);  // %.17g, or null if not finite
  static std::string quoted(const std::string& v);
  static std::string array(const std::vector<double>& values);

 private:
  std::vector<std::string> entries_;
};

}  // namespace ddb::app
