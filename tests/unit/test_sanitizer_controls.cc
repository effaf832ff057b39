// The sanitizer stage's positive controls (scripts/test.sh, docs/reference/guarantees.md §4): a
// build configured for the sanitizers (DDB_EXPECT_SANITIZERS, which the stage defines) has them on,
// and they stop a heap overflow and a signed overflow, each by name. Without these, a compiler or
// a flag that dropped them would leave the stage passing and checking nothing. Other builds
// compile this file to no test.
#include <gtest/gtest.h>

#include <climits>
#include <vector>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DDB_ADDRESS_SANITIZER_ON 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define DDB_ADDRESS_SANITIZER_ON 1
#endif

#ifdef DDB_EXPECT_SANITIZERS
#ifndef DDB_ADDRESS_SANITIZER_ON
#error "DDB_EXPECT_SANITIZERS is defined, but this compile has no AddressSanitizer"
#endif

namespace ddb::test {
namespace sanitizer_controls_tests {

volatile int sink = 0;

TEST(Sanitizers, AddressSanitizerStopsAReadPastAHeapBlock) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(
      {
        std::vector<int> values(4, 1);
        volatile const int* data = values.data();
        sink = data[4];
      },
      "heap-buffer-overflow");
}

TEST(Sanitizers, UndefinedBehaviorSanitizerStopsASignedOverflow) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(
      {
        volatile int largest = INT_MAX;
        sink = largest + 1;
      },
      "signed integer overflow");
}

}  // namespace sanitizer_controls_tests
}  // namespace ddb::test
#endif
