// The distributed Poisson solve (docs/design/distributed.md) on 1–4 ranks against the serial
// HoppeYauLaplacian::solve, and the bytes each rank sends against counts derived by hand.
#include <ddb/core/errors.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/distributed_poisson_solver.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "mpi_test_support.h"

namespace ddb {
namespace distributed_poisson_tests {

using test::randomVorticity;
using test::relativeDistance;

class DistributedPoissonTest : public test::SizeAndBlockTest {};

TEST_P(DistributedPoissonTest, MatchesTheSerialSolve) {
  const Eigen::MatrixXcd w = randomVorticity(n(), 41);
  DistributedMatrix dw(grid_, n(), block()), dp(grid_, n(), block());
  dw.scatterFrom(w);
  DistributedPoissonSolver solver(dw.layout());
  solver.solve(dw, dp);
  const Eigen::MatrixXcd p = dp.gather();
  // In place: the result replaces W.
  solver.solve(dw, dw);
  const Eigen::MatrixXcd p_in_place = dw.gather();
  if (grid_.rank() == 0) {
    Eigen::MatrixXcd reference;
    HoppeYauLaplacian(n()).solve(w, reference);
    EXPECT_LT(relativeDistance(p, reference), 1e-13);
    EXPECT_LT(relativeDistance(p_in_place, reference), 1e-13);
  }
}

// Quasi-geostrophy's Δ − κ² (every block definite, nothing pinned) as the serial solver has it.
TEST_P(DistributedPoissonTest, MatchesTheSerialHelmholtzSolve) {
  const double kappa_squared = 2.5;
  const Eigen::MatrixXcd w = randomVorticity(n(), 43);
  DistributedMatrix dw(grid_, n(), block()), dp(grid_, n(), block());
  dw.scatterFrom(w);
  DistributedPoissonSolver solver(dw.layout(), kappa_squared);
  solver.solve(dw, dp);
  const Eigen::MatrixXcd p = dp.gather();
  if (grid_.rank() == 0) {
    Eigen::MatrixXcd reference;
    HoppeYauLaplacian(n(), kappa_squared).solve(w, reference);
    EXPECT_LT(relativeDistance(p, reference), 1e-13);
  }
}

TEST(DistributedPoissonSolver, RefusesAnotherBlockSize) {
  const test::TestGrid grid;
  const DistributedMatrix w(grid, 8, 3);
  DistributedMatrix other(grid, 8, 4);
  DistributedPoissonSolver solver(w.layout());
  EXPECT_THROW(solver.solve(w, other), InvalidArgument);
}

INSTANTIATE_TEST_SUITE_P(SizesAndBlocks, DistributedPoissonTest,
                         testing::Combine(testing::Values(4, 16, 33, 64), testing::Values(1, 5, 7)),
                         test::sizeAndBlockName);

// N = 4, block 1: rank r holds the entries (i, j) with i mod rows = r / cols and
// j mod cols = r mod cols; diagonal m goes to rank q(m) mod P with q = 0, 1, 2, 3, 4, 5, 6
// for m = 0, 1, −1, 2, −2, 3, −3. Counting, rank by rank, the entries it holds whose
// diagonal is owned elsewhere (sent there) plus the entries of its own diagonals that
// another rank holds (sent back), at 16 bytes each (docs/design/distributed.md works 1×2 and 2×1):
//   1×2: 2 + 4, 4 + 2;  2×1: 4 + 6, 6 + 4;
//   1×3: 4 + 3, 2 + 3, 3 + 3;  3×1: 4 + 3, 3 + 4, 3 + 3;
//   2×2: 1 + 3, 1 + 1, 1 + 1, 3 + 1.
TEST(DistributedPoissonSolver, SendsTheBytesCountedByHand) {
  const test::TestGrid grid;
  const std::map<std::pair<int, int>, std::vector<std::int64_t>> expected = {
      {{1, 1}, {0}},           {{1, 2}, {96, 96}},       {{2, 1}, {160, 160}},
      {{1, 3}, {112, 80, 96}}, {{3, 1}, {112, 112, 96}}, {{2, 2}, {64, 32, 32, 64}}};
  const auto counts = expected.find({grid.rows(), grid.cols()});
  if (counts == expected.end()) {
    GTEST_SKIP() << "no count for a " << grid.rows() << "x" << grid.cols() << " grid";
  }
  const DistributedMatrix w(grid, 4, 1);
  const DistributedPoissonSolver solver(w.layout());
  EXPECT_EQ(solver.bytesSentPerSolve(), counts->second[static_cast<std::size_t>(grid.rank())]);
}

}  // namespace distributed_poisson_tests
}  // namespace ddb
