// The distributed backend's eigenbasis (distributed/distributed_eigenbasis.h) on 1–4 ranks, N
// from one block (where ScaLAPACK's tridiagonal solver runs on one process) to many:
// the phases against Eigen's eigensolver of the gathered −ix, the same bits on every rank;
// Ad*_{exp(sx)} − id against Eigen's matrix exponential; both phase functions against the
// dense backend's eigenbasis; the result exactly skew-Hermitian; a non-finite x refused on
// every rank.
#include <ddb/core/phase_function.h>
#include <ddb/core/skew_hermitian_eigenbasis.h>
#include <ddb/distributed/distributed_backend.h>
#include <ddb/distributed/distributed_eigenbasis.h>
#include <ddb/distributed/distributed_matrix.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "mpi_test_support.h"

namespace ddb {
namespace {

using test::randomComplexMatrix;
using test::relativeDistance;

// A skew-Hermitian matrix of spectral radius about `radius`.
Eigen::MatrixXcd randomSkewHermitian(int n, unsigned seed, double radius) {
  const Eigen::MatrixXcd a = randomComplexMatrix(n, seed);
  Eigen::MatrixXcd x = a - a.adjoint();
  const Eigen::VectorXd theta = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(
                                    Eigen::MatrixXcd(x * std::complex<double>(0.0, -1.0)))
                                    .eigenvalues();
  x *= radius / theta.cwiseAbs().maxCoeff();
  return x;
}

class DistributedEigenbasisTest : public test::SizeAndBlockTest {
 protected:
  DistributedMatrix scattered(const Eigen::MatrixXcd& global) {
    DistributedMatrix x(grid_, n(), block());
    x.scatterFrom(global);
    return x;
  }
};

// θ of −ix, ascending, against Eigen's SelfAdjointEigenSolver; bit for bit alike on every rank.
TEST_P(DistributedEigenbasisTest, PhasesAreTheEigenvaluesOfMinusIxOnEveryRank) {
  const Eigen::MatrixXcd x = randomSkewHermitian(n(), 31, 1.0);
  DistributedEigenbasis basis;
  ASSERT_TRUE(basis.compute(scattered(x)));
  const Eigen::VectorXd reference = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(
                                        Eigen::MatrixXcd(x * std::complex<double>(0.0, -1.0)))
                                        .eigenvalues();
  EXPECT_LT((basis.phases() - reference).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_DOUBLE_EQ(basis.adRadius(), basis.phases()(n() - 1) - basis.phases()(0));
  Eigen::VectorXd on_rank_zero = basis.phases();
  MPI_Bcast(on_rank_zero.data(), n(), MPI_DOUBLE, 0, grid_.comm());
  EXPECT_TRUE(on_rank_zero == basis.phases());
}

// Ad*_{exp(sx)} μ − μ = exp(−sx) μ exp(sx) − μ, with Eigen's matrix exponential (a Padé
// approximant with scaling and squaring: no eigenbasis).
TEST_P(DistributedEigenbasisTest, CoadjointIncrementIsTheConjugationByEigensExponential) {
  const Eigen::MatrixXcd x = randomSkewHermitian(n(), 32, 2.0),
                         mu = randomSkewHermitian(n(), 33, 1.0);
  const double scale = 0.7;
  DistributedEigenbasis basis;
  ASSERT_TRUE(basis.compute(scattered(x)));
  DistributedMatrix out;
  basis.apply(PhaseFunction::kCoadjointIncrement, scale, scattered(mu), out);
  const Eigen::MatrixXcd result = out.gather();
  if (grid_.rank() == 0) {
    const Eigen::MatrixXcd g = (scale * x).exp();
    const Eigen::MatrixXcd reference = g.adjoint() * mu * g - mu;
    EXPECT_LT((result - reference).norm(), 1e-13 * mu.norm());
    EXPECT_TRUE(result == Eigen::MatrixXcd(-result.adjoint())) << "not skew-Hermitian bit for bit";
  }
}

// Both functions against the dense backend's eigenbasis on the whole matrices, and `out` may
// be `in`.
TEST_P(DistributedEigenbasisTest, BothFunctionsAgreeWithTheDenseEigenbasis) {
  const Eigen::MatrixXcd x = randomSkewHermitian(n(), 34, 2.5),
                         a = randomSkewHermitian(n(), 35, 1.0);
  DistributedEigenbasis basis;
  ASSERT_TRUE(basis.compute(scattered(x)));
  SkewHermitianEigenbasis<Eigen::MatrixXcd> dense;
  ASSERT_TRUE(dense.compute(x));
  for (const PhaseFunction f :
       {PhaseFunction::kCoadjointIncrement, PhaseFunction::kInverseDexpInverseDual}) {
    for (const double scale : {1.0, -0.4}) {
      DistributedMatrix inout = scattered(a);
      basis.apply(f, scale, inout, inout);
      const Eigen::MatrixXcd result = inout.gather();
      if (grid_.rank() == 0) {
        Eigen::MatrixXcd reference;
        dense.apply(f, scale, a, reference);
        EXPECT_LT(relativeDistance(result, reference), 1e-13)
            << "function " << static_cast<int>(f) << ", scale " << scale;
      }
    }
  }
}

// A NaN on any one rank's entries: false on every rank, none left waiting.
TEST_P(DistributedEigenbasisTest, RefusesANonFiniteMatrixOnEveryRank) {
  Eigen::MatrixXcd x = randomSkewHermitian(n(), 36, 1.0);
  x(n() - 1, n() / 2) = NAN;
  DistributedEigenbasis basis;
  EXPECT_FALSE(basis.compute(scattered(x)));
  EXPECT_TRUE(basis.compute(scattered(randomSkewHermitian(n(), 37, 1.0))));
}

INSTANTIATE_TEST_SUITE_P(SizesAndBlocks, DistributedEigenbasisTest,
                         testing::Combine(testing::Values(4, 16, 33, 64), testing::Values(5, 7)),
                         test::sizeAndBlockName);

}  // namespace
}  // namespace ddb
