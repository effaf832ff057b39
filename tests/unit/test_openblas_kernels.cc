// core/openblas_kernels.h: the advice to set OPENBLAS_CORETYPE when OpenBLAS runs kernels below
// the CPU's (docs/guide/performance.md, "OpenBLAS's kernels"), against the rule written out
// here, and the process's own core and CPU against OPENBLAS_CORETYPE and /proc/cpuinfo.
#include <ddb/core/openblas_kernels.h>
#include <gmock/gmock.h>

#include <Eigen/Core>
#include <cctype>
#include <cstdlib>
#include <string>

#include "cpu_flags.h"

namespace ddb::test {
namespace {

using ::testing::HasSubstr;

TEST(OpenblasKernels, AdviceNamesTheCoreAndTheVariableOnlyBelowTheCpusVectorUnits) {
  const std::string prescott = openblasKernelAdvice("Prescott", CpuVectorUnits::kAvx512);
  EXPECT_THAT(prescott, HasSubstr("Prescott"));
  EXPECT_THAT(prescott, HasSubstr("OPENBLAS_CORETYPE=SkylakeX"));
  EXPECT_THAT(openblasKernelAdvice("Prescott", CpuVectorUnits::kAvx2),
              HasSubstr("OPENBLAS_CORETYPE=Haswell"));
  EXPECT_THAT(openblasKernelAdvice("Sandybridge", CpuVectorUnits::kAvx2),
              HasSubstr("OPENBLAS_CORETYPE=Haswell"));
  EXPECT_THAT(openblasKernelAdvice("Core2", CpuVectorUnits::kAvx512), HasSubstr("SkylakeX"));
  // Kernels with AVX2 or AVX-512 are left alone (Haswell on an AVX-512 CPU is a user's choice
  // within a factor of about 1.4, not the generic kernels' several times).
  for (const char* wide :
       {"Haswell", "HASWELL", "Zen", "Excavator", "SkylakeX", "Cooperlake", "SapphireRapids"}) {
    EXPECT_EQ(openblasKernelAdvice(wide, CpuVectorUnits::kAvx512), "") << wide;
  }
  // Nothing better to name: an older CPU, or a BLAS that is not OpenBLAS.
  EXPECT_EQ(openblasKernelAdvice("Prescott", CpuVectorUnits::kOlder), "");
  EXPECT_EQ(openblasKernelAdvice("", CpuVectorUnits::kAvx512), "");
}

TEST(OpenblasKernels, TheCpusVectorUnitsAreThoseProcCpuinfoLists) {
  if (cpuFlags().empty()) GTEST_SKIP() << "no /proc/cpuinfo flags";
  const CpuVectorUnits expected = cpuHasAvx512() && cpuHasAvx2() ? CpuVectorUnits::kAvx512
                                  : cpuHasAvx2()                 ? CpuVectorUnits::kAvx2
                                                                 : CpuVectorUnits::kOlder;
  EXPECT_EQ(cpuVectorUnits(), expected);
}

// A DYNAMIC_ARCH OpenBLAS (Debian's) takes OPENBLAS_CORETYPE = Prescott or Haswell as the core it
// runs (scripts/test.sh runs the numerical suites under both): the core read back is the one
// set, whatever its case. An OpenBLAS built for one target ignores the variable.
TEST(OpenblasKernels, TheCoreReadBackIsTheOneOpenblasCoretypeSets) {
  // A product through the BLAS (EIGEN_USE_BLAS), as the library's are: without one the linker
  // would drop the BLAS from this program, and there would be no core to read.
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(64, 64);
  ASSERT_EQ(identity * identity, identity);
  const std::string core = openblasCoreName();
  if (core.empty()) GTEST_SKIP() << "the BLAS is not OpenBLAS";
  if (openblasConfig().find("DYNAMIC_ARCH") == std::string::npos) {
    GTEST_SKIP() << "OpenBLAS built for one target: " << openblasConfig();
  }
  const auto lower = [](std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
  };
  const char* set = std::getenv("OPENBLAS_CORETYPE");
  if (set == nullptr || (lower(set) != "prescott" && lower(set) != "haswell")) {
    GTEST_SKIP() << "OPENBLAS_CORETYPE is not Prescott or Haswell; OpenBLAS runs " << core;
  }
  EXPECT_EQ(lower(core), lower(set));
  if (lower(set) == "prescott" && cpuHasAvx2()) {
    EXPECT_NE(openblasKernelAdvice(), "");
  }
}

}  // namespace
}  // namespace ddb::test
