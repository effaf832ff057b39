// The main of the MPI tests: every rank runs every test (the distributed operations are
// collective); rank 0 prints GoogleTest's usual report, the other ranks only their failed
// assertions, prefixed with their rank, and every rank exits with the worst result of all.
// --grid-rows=R (after GoogleTest's own flags) runs the tests on a grid of R rows
// (mpi_test_support.h, TestGrid); anything else left over is refused.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "mpi_test_support.h"

namespace {

class RankFailurePrinter : public testing::EmptyTestEventListener {
 public:
  explicit RankFailurePrinter(int rank) : rank_(rank) {}
  void OnTestPartResult(const testing::TestPartResult& result) override {
    if (!result.failed()) return;
    std::fprintf(stderr, "[rank %d] %s:%d: %s\n", rank_,
                 result.file_name() ? result.file_name() : "?", result.line_number(),
                 result.summary());
  }

 private:
  int rank_;
};

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  constexpr const char* kRows = "--grid-rows=";
  for (int i = 1; i < argc; ++i) {
    char* end = nullptr;
    const long rows = std::strncmp(argv[i], kRows, std::strlen(kRows)) == 0
                          ? std::strtol(argv[i] + std::strlen(kRows), &end, 10)
                          : 0;
    if (rows < 1 || rows > 1024 || *end != '\0') {
      if (rank == 0) std::fprintf(stderr, "unknown argument %s (--grid-rows=R only)\n", argv[i]);
      MPI_Finalize();
      return 2;
    }
    ddb::test::gridRowsAsked() = static_cast<int>(rows);
  }
  if (rank != 0) {
    auto& listeners = testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new RankFailurePrinter(rank));
  }
  int result = RUN_ALL_TESTS(), worst = 0;
  MPI_Allreduce(&result, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return worst;
}
