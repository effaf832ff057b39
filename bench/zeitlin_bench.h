// The fluid's benchmarks (docs/reference/command-lines-and-files.md, ddb-bench):
// zeitlin/<method>/<N> at α = 0.5, zeitlin-euler/ddb-cay/<N> at α = 0 and zeitlin/gemm/<N>, the
// cost unit.
#pragma once

namespace ddb::bench {

void registerZeitlinBenchmarks();

}  // namespace ddb::bench
