#include "common/progress.h"

#include <spdlog/fmt/fmt.h>
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

void Progress::update(const std::string& label, long done, long total,
                      const std::function<std::string()>& detail) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (label != rate_label_ || done < rate_done_) {
    rate_label_ = label;
    rate_done_ = done;
    rate_start_ = now;
  }
  if (shown_ && now - last_ < std::chrono::milliseconds(100)) return;
  const double percent = total > 0 ? 100.0 * static_cast<double>(done) / total : 100.0;
  // fmt, not printf: the line ignores the locale, as the files do (format.h).
  std::string line = fmt::format("{}: {:5.1f}% ({}/{} steps", label, percent, done, total);
  const double seconds = std::chrono::duration<double>(now - rate_start_).count();
  if (done > rate_done_ && seconds > 0) {
    const double rate = static_cast<double>(done - rate_done_) / seconds;
    line += fmt::format(", {:.3g} steps/s, {:.0f} s left", rate,
                        static_cast<double>(total - done) / rate);
  }
  show(line + ")" + (detail ? "  " + detail() : ""));
}

void Progress::clear() {
  if (!enabled_ || !shown_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  shown_ = false;
}

}  // namespace ddb::app
