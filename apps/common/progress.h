// A progress line on stderr, redrawn in place, shown only when stderr is a terminal
// (so logs and test output stay clean) and never with --quiet. Updates are throttled,
// so callers may report as often as they like.
#pragma once

#include <chrono>
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
  /// Shows "<label>: <percent> (<done>/<total> steps)" at most ten times a second.
  void update(const std::string& label, long done, long total);
  /// Erases the line, e.g. before a log message.
  void clear();

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace ddb::app
