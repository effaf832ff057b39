// A progress line on stderr, redrawn in place, shown only when stderr is a terminal
// (so logs and test output stay clean) and never with --quiet. Updates are throttled,
// so callers may report as often as they like.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace ddb::app {

class Progress {
 public:
  explicit Progress(bool quiet);
  /// Clears the line.
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Shows `label` now.
  void show(const std::string& label);
  /// Shows "<label>: <percent> (<done>/<total> steps, <rate> steps/s, <time> left) <detail>"
  /// at most ten times a second. The rate counts from the first update of this label;
  /// `detail` is called only when the line is drawn, so it may be costly.
  void update(const std::string& label, long done, long total,
              const std::function<std::string()>& detail = {});
  /// Erases the line, e.g. before a log message.
  void clear();

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_;
  std::string rate_label_;
  long rate_done_ = 0;
  std::chrono::steady_clock::time_point rate_start_;
};

}  // namespace ddb::app
