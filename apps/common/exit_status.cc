#include "common/exit_status.h"

#include <cstdio>
#include <exception>

namespace ddb::app {

int runMain(const char* app, int (*body)(int, char**), int argc, char** argv) noexcept {
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
