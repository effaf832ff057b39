// evaluationScratch: the workspaces of a const evaluation (a Hamiltonian's value()) on matrices
// X, chosen once for every system that keeps them: per thread for dense matrices (a system is
// shared by threads, Python's integrate() runs without the GIL, and OrbitNewton's line searches
// evaluate H inside a step, which does not allocate: tests/unit/test_allocations.cc), the
// object's own for other backends, whose evaluations are collective and so one at a time.
#pragma once

#include <ddb/core/matrix_traits.h>

namespace ddb::detail {

/// This thread's Scratch for dense X (one per Scratch type and thread), else `own`.
template <class X, class Scratch>
Scratch& evaluationScratch(Scratch& own) {
  if constexpr (isEigenMatrix<X>) {
    thread_local Scratch per_thread;
    return per_thread;
  } else {
    return own;
  }
}

}  // namespace ddb::detail
