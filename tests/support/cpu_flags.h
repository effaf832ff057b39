// The CPU's feature flags as the kernel reports them (/proc/cpuinfo), for the tests of
// core/openblas_kernels.h: a source that code does not read (it asks the compiler's
// __builtin_cpu_supports).
#pragma once

#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace ddb::test {

/// The flags of the first processor in /proc/cpuinfo; empty where there is no such file.
inline std::set<std::string> cpuFlags() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("flags", 0) != 0) continue;
    std::istringstream words(line.substr(line.find(':') + 1));
    std::set<std::string> flags;
    for (std::string word; words >> word;) flags.insert(word);
    return flags;
  }
  return {};
}

/// Whether the CPU has AVX2 with FMA, what OpenBLAS's Haswell kernels need.
inline bool cpuHasAvx2() {
  const auto flags = cpuFlags();
  return flags.count("avx2") > 0 && flags.count("fma") > 0;
}

/// Whether the CPU has AVX-512 F, BW, DQ and VL, what OpenBLAS's SkylakeX kernels use.
inline bool cpuHasAvx512() {
  const auto flags = cpuFlags();
  return flags.count("avx512f") > 0 && flags.count("avx512bw") > 0 && flags.count("avx512dq") > 0 &&
         flags.count("avx512vl") > 0;
}

}  // namespace ddb::test
