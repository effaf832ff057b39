#include "common/progress.h"

#include <unistd.h>

#include <cstdio>

namespace ddb::app {

Progress::Progress(bool quiet) : enabled_(!quiet && ::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { clear(); }

void Progress::show(const std::string& label) {
  if (!enabled_) return;
  std::fprintf(stderr, "\r\033[K%s", label.c_str());
  std::fflush(stderr);
  shown_ = true;
  last_ = std::chrono::steady_clock::now();
}

void Progress::update(const std::string& label, long done, long total) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (shown_ && now - last_ < std::chrono::milliseconds(100)) return;
  const double percent = total > 0 ? 100.0 * static_cast<double>(done) / total : 100.0;
  char line[256];
  std::snprintf(line, sizeof line, "%s: %5.1f%% (%ld/%ld steps)", label.c_str(), percent, done,
                total);
  show(line);
}

void Progress::clear() {
  if (!enabled_ || !shown_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  shown_ = false;
}

}  // namespace ddb::app
