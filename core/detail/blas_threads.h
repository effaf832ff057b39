// How many threads the BLAS runs a call on, where the BLAS says: OpenBLAS's
// openblas_get_num_threads(), looked up as weak symbols so that any other BLAS links too
// (it then reports 0, unknown). The library splits a product among its own threads only
// under a single-threaded BLAS (core/matrix_backend.h): two thread pools on the same cores
// slow each other (docs/design/architecture.md, "Threads"). And only under OpenBLAS's pthreads
// build (openblas_get_parallel() == 1), which may be called from several threads at once; its
// serial and OpenMP builds are reported as unknown.
#pragma once

#include <ddb/core/thread_pool.h>

#include <algorithm>

extern "C" int openblas_get_num_threads(void) __attribute__((weak));
extern "C" int openblas_get_parallel(void) __attribute__((weak));

namespace ddb::detail {

/// The BLAS's thread count, 0 when unknown.
inline int blasThreadCount() {
  constexpr int kPthreads = 1;  // openblas_get_parallel()'s value for the pthreads build
  if (openblas_get_num_threads == nullptr || openblas_get_parallel == nullptr) return 0;
  return openblas_get_parallel() == kPthreads ? openblas_get_num_threads() : 0;
}

/// The columns of one BLAS call when a product or a solve of `cols` columns is split among
/// the library's threads: set by the size alone, since the BLAS rounds a product's columns
/// differently in calls of other widths, so that the results do not depend on the number of
/// threads; at most 16 chunks, so that the left factor is not packed again too often.
inline long blasChunkWidth(long cols) { return std::max<long>(64, (cols + 15) / 16); }

/// f(first, count) over the columns [0, cols) of a product or a solve, one BLAS call each:
/// once over all of them, or, under a single-threaded BLAS, by chunks of blasChunkWidth(cols)
/// on the library's threads.
template <class F>
void forBlasColumnChunks(long cols, const F& f) {
  if (blasThreadCount() != 1) {
    f(0L, cols);
  } else {
    ThreadPool::instance().forColumnChunks(cols, blasChunkWidth(cols), f);
  }
}

}  // namespace ddb::detail
