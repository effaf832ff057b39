// Magnetohydrodynamics on the sphere on matrices distributed over MPI ranks
// (distributed/distributed_zeitlin_mhd.h) against the dense magnetic fluid on 1–4 ranks: the
// distributed Laplacian (DistributedPoissonSolver::apply) is the dense one's, bit for bit; every
// method that runs on SU(N) ⋉ su(N)* (the exponential ones through the dual numbers' eigenbasis on
// the distributed one, core/dual_eigenbasis.h) takes the dense steps to 1e-13 over 20 steps at N =
// 16 and 33 with block sizes that do not divide N; the energy agrees and the Casimirs of the
// gathered state stay.
#include <ddb/distributed/distributed_zeitlin_mhd.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "mhd_casimir_drift.h"
#include "mpi_test_support.h"

namespace ddb {
namespace distributed_mhd_tests {

using test::relativeDistance;

TEST(DistributedMhd, TheLaplacianIsTheDenseOneToTheBit) {
  const test::TestGrid grid;
  for (const auto& [n, block] : {std::pair{16, 5}, {33, 7}}) {
    const Eigen::MatrixXcd Theta = randomVorticity(n, 4);
    Eigen::MatrixXcd expected(n, n);
    HoppeYauLaplacian(n).apply(Theta, expected);
    DistributedMatrix Td(grid, n, block), Bd(grid, n, block);
    Td.scatterFrom(Theta);
    DistributedPoissonSolver(Td.layout()).apply(Td, Bd);
    const Eigen::MatrixXcd B = Bd.gather();
    if (grid.rank() == 0) {
      EXPECT_EQ(std::memcmp(B.data(), expected.data(), sizeof(std::complex<double>) * B.size()), 0)
          << "N = " << n;
    }
  }
}

TEST(DistributedMhd, EveryMethodTakesTheDenseSteps) {
  const test::TestGrid grid;
  for (const auto& [n, block] : {std::pair{16, 5}, {33, 7}}) {
    const double alpha = 0.5, h = 0.01;
    const Eigen::MatrixXcd W0 = randomVorticity(n, 1);
    const Eigen::MatrixXcd Theta0 = 0.02 / double(n) * randomVorticity(n, 2);
    const auto dense_mhd = makeZeitlinMhd(n, alpha);
    DualMatrix<DistributedMatrix> start{DistributedMatrix(grid, n, block),
                                        DistributedMatrix(grid, n, block)};
    start.real.scatterFrom(Theta0);
    start.eps.scatterFrom(W0);
    const auto mhd = makeDistributedZeitlinMhd(start.real.layout(), alpha);
    for (const MethodInfo& m : kMethods) {
      if (!methodApplies(m, *dense_mhd)) continue;
      const std::string what = std::string(m.name) + ", N = " + std::to_string(n);
      ASSERT_TRUE(methodApplies(m, *mhd)) << what;
      // 20 steps; a composition's step is 3 or 7 steps of its base (which takes its 20 here):
      // 4 of them. On more ranks than cores, ddb6-exp's 20 steps took 40 % of the test.
      const int steps = m.kind == MethodKind::kComposition ? 4 : 20;
      DualMatrix<Eigen::MatrixXcd> mu = zeitlinMhdState(W0, Theta0);
      const auto dense = makeMethod<DualNumberSUN>(m, dense_mhd);
      for (int k = 0; k < steps; ++k) dense->advance(mu, k * h, h);
      DualMatrix<DistributedMatrix> md = start;
      const auto method = makeMethod<DistributedDualNumberSUN>(m, mhd);
      for (int k = 0; k < steps; ++k) method->advance(md, k * h, h);
      const double energy = mhd->energy(md);
      const Eigen::MatrixXcd W = md.eps.gather(), Theta = md.real.gather();
      if (grid.rank() == 0) {
        EXPECT_LT(relativeDistance(W, mu.eps), 1e-13) << what;
        EXPECT_LT(relativeDistance(Theta, mu.real), 1e-13) << what;
        EXPECT_GT(relativeDistance(W, W0), 1e-4) << what;
        EXPECT_LT(std::abs(energy - dense_mhd->energy(mu)), 1e-13 * dense_mhd->energy(mu)) << what;
        if (m.keeps_casimirs) {
          EXPECT_LT(test::mhdCasimirDrift(zeitlinMhdState(W0, Theta0), zeitlinMhdState(W, Theta)),
                    1e-12)
              << what;
        }
      }
    }
  }
}

}  // namespace distributed_mhd_tests
}  // namespace ddb
