// Which kernels OpenBLAS runs, and whether they are below what the CPU supports. OpenBLAS picks
// its kernels by the CPU at load time; a CPU newer than the OpenBLAS (Debian 12's 0.3.21 on
// recent Intel Xeons) gets the generic Prescott kernels, several times slower on the fluid's
// products than the AVX2 or AVX-512 ones the CPU can run (docs/guide/performance.md,
// "OpenBLAS's kernels"). The apps and the Python module say so once, with the variable to set.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

#if defined(__GNUC__) && defined(__ELF__)
// Weak: resolved only when the BLAS this process loaded is OpenBLAS (another BLAS, or none,
// leaves it null).
extern "C" char* openblas_get_corename(void) __attribute__((weak));
extern "C" char* openblas_get_config(void) __attribute__((weak));
#endif

namespace ddb {

/// What the CPU can run, as far as OpenBLAS's kernel families go.
enum class CpuVectorUnits { kOlder, kAvx2, kAvx512 };

/// The OpenBLAS core this process's BLAS runs ("Prescott", "Haswell", "SkylakeX", …), or "" when
/// the BLAS is not OpenBLAS (or the platform cannot tell).
inline std::string openblasCoreName() {
#if defined(__GNUC__) && defined(__ELF__)
  if (openblas_get_corename != nullptr) {
    const char* name = openblas_get_corename();
    if (name != nullptr) return name;
  }
#endif
  return "";
}

/// OpenBLAS's build configuration ("OpenBLAS 0.3.21 ... DYNAMIC_ARCH ..."), or "" when the BLAS
/// is not OpenBLAS. Only a DYNAMIC_ARCH build picks its kernels at load time and obeys
/// OPENBLAS_CORETYPE; one built for a TARGET runs that target's kernels.
inline std::string openblasConfig() {
#if defined(__GNUC__) && defined(__ELF__)
  if (openblas_get_config != nullptr) {
    const char* config = openblas_get_config();
    if (config != nullptr) return config;
  }
#endif
  return "";
}

/// This CPU's vector units: AVX-512 (F, BW, DQ, VL, what OpenBLAS's SkylakeX kernels use), AVX2
/// with FMA (its Haswell kernels), or older.
inline CpuVectorUnits cpuVectorUnits() {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl")) {
    return CpuVectorUnits::kAvx512;
  }
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return CpuVectorUnits::kAvx2;
#endif
  return CpuVectorUnits::kOlder;
}

/// The advice for OpenBLAS core `core` on a CPU with `units`: empty when the core uses AVX2 or
/// AVX-512 kernels (or the CPU has neither, or the BLAS is not OpenBLAS), else one sentence
/// naming the core and the OPENBLAS_CORETYPE value that uses what the CPU supports.
inline std::string openblasKernelAdvice(std::string_view core, CpuVectorUnits units) {
  if (core.empty() || units == CpuVectorUnits::kOlder) return "";
  std::string lower(core);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  // OpenBLAS's x86-64 cores whose kernels use AVX2 with FMA, or AVX-512.
  for (std::string_view wide :
       {"haswell", "zen", "excavator", "skylakex", "cooperlake", "sapphirerapids"}) {
    if (lower == wide) return "";
  }
  const char* suggested = units == CpuVectorUnits::kAvx512 ? "SkylakeX" : "Haswell";
  return "OpenBLAS runs its " + std::string(core) + " kernels on this CPU, which supports " +
         (units == CpuVectorUnits::kAvx512 ? "AVX-512" : "AVX2") +
         ": matrix products run several times slower than they could; set OPENBLAS_CORETYPE=" +
         suggested + " (docs/guide/performance.md, \"OpenBLAS's kernels\")";
}

/// openblasKernelAdvice for this process's OpenBLAS and CPU.
inline std::string openblasKernelAdvice() {
  return openblasKernelAdvice(openblasCoreName(), cpuVectorUnits());
}

}  // namespace ddb
