// malloc replaced by a counting forwarder to glibc's own entry point (see the header).
#include "malloc_counter.h"

#include <atomic>
#include <cstddef>

namespace {
std::atomic<long> count{0};
}  // namespace

extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* malloc(std::size_t size) {
  count.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}

namespace ddb::tools {
long mallocCount() { return count.load(std::memory_order_relaxed); }
}  // namespace ddb::tools
