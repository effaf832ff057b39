// SIGINT and SIGTERM as requests to stop a long run after its current step, so that it
// can write its outputs and a checkpoint (docs/reference/command-lines-and-files.md,
// "Checkpoints"). While a StopSignals lives, the first such signal is only recorded; the run polls
// received() between steps. A second SIGINT ends the process at once (exit status 130) without
// touching a file: the last checkpoint, which is only ever replaced by a rename, stays
// intact.
#pragma once

namespace ddb::app {

class StopSignals {
 public:
  /// Installs the handlers; the destructor restores the previous ones.
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  /// The first signal received (SIGINT or SIGTERM), or 0.
  int received() const;
  /// The exit status of a run stopped by `signal`: 128 + its number (130, 143).
  static int exitStatus(int signal) { return 128 + signal; }
  /// "SIGINT" or "SIGTERM".
  static const char* name(int signal);
};

}  // namespace ddb::app
