#include "common/exit_status.h"

#include <ddb/core/thread_pool.h>

#include <cstdio>
#include <exception>

namespace ddb::app {

int runMain(const char* app, int (*body)(int, char**), int argc, char** argv) noexcept {
  try {
    // The library's threads start here, before anything is written: a bad DDB_NUM_THREADS
    // is bad input, not a failure in the middle of a run (core/thread_pool.h).
    ThreadPool::instance();
  } catch (const InvalidArgument& e) {
    std::fprintf(stderr, "%s: %s\n", app, e.what());
    return kExitBadInput;
  }
  try {
    return body(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s\n", app, e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", app, e.what());
  } catch (...) {
    std::fprintf(stderr, "%s: unknown error\n", app);
  }
  return kExitFailed;
}

}  // namespace ddb::app
