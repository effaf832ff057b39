// Element-wise passes over a matrix split by column ranges among the library's threads
// (core/thread_pool.h): the O(N²) work between a step's products (docs/design/architecture.md,
// "Threads"). Each entry is computed by the same expression as in a serial pass, so the
// results are the same bits whatever the number of threads.
#pragma once

#include <ddb/core/thread_pool.h>

namespace ddb {

/// dst = expr, entry by entry (a matrix dst takes expr's shape). expr may read dst only at
/// the entry it assigns (as in x = 2x + y, not x = xᴴ).
template <class Dst, class Expr>
void assignInParallel(Dst&& dst, const Expr& expr) {
  dst.resize(expr.rows(), expr.cols());
  ThreadPool::instance().forColumnRanges(dst.rows(), dst.cols(), [&](long first, long count) {
    dst.middleCols(first, count) = expr.middleCols(first, count);
  });
}

/// dst += expr, entry by entry, with assignInParallel's condition on expr.
template <class Dst, class Expr>
void addInParallel(Dst&& dst, const Expr& expr) {
  ThreadPool::instance().forColumnRanges(dst.rows(), dst.cols(), [&](long first, long count) {
    dst.middleCols(first, count) += expr.middleCols(first, count);
  });
}

}  // namespace ddb
