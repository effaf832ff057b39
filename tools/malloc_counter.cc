// malloc, calloc and realloc replaced by counting forwarders to glibc's own entry points (see
// the header). calloc too: GCC turns a malloc followed by zeroing (Eigen's Zero() on a fresh
// matrix) into one calloc call.
#include "malloc_counter.h"

#include <atomic>
#include <cstddef>

namespace {
std::atomic<long> count{0};
}  // namespace

extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* __libc_calloc(std::size_t count, std::size_t size);
extern "C" void* __libc_realloc(void* pointer, std::size_t size);
extern "C" void* malloc(std::size_t size) {
  count.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
extern "C" void* calloc(std::size_t elements, std::size_t size) {
  count.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(elements, size);
}
extern "C" void* realloc(void* pointer, std::size_t size) {
  count.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(pointer, size);
}

namespace ddb::tools {
long mallocCount() { return count.load(std::memory_order_relaxed); }
}  // namespace ddb::tools
