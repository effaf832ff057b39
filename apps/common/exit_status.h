// The exit statuses every app uses (docs/reference/command-lines-and-files.md) and the one place
// that maps exceptions to them, so that no error reaches std::terminate:
//   0  success;
//   1  a run failed, or an I/O error (the message names the file); files of the runs
//      that succeeded are written, a file that could not be completed is not;
//   2  bad input (a usage error naming the flag); nothing is written.
#pragma once

#include <stdexcept>
#include <string>

namespace ddb::app {

enum ExitStatus : int { kExitOk = 0, kExitFailed = 1, kExitBadInput = 2 };

/// Bad input on the command line: exit status 2, thrown only before anything is written.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file that could not be written; the message names it. Exit status 1.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Runs body(argc, argv) and returns its status; an exception becomes a one-line
/// message "<app>: <what>" on stderr and status 2 (UsageError) or 1 (anything else).
int runMain(const char* app, int (*body)(int, char**), int argc, char** argv) noexcept;

}  // namespace ddb::app
