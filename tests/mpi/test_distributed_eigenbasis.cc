// The distributed backend's eigenbasis (distributed/distributed_eigenbasis.h) on 1–4 ranks, N
// from one block (where ScaLAPACK's tridiagonal solver runs on one process) to many:
// the phases against Eigen's eigensolver of the gathered −ix, the same bits on every rank;
// Ad*_{exp(sx)} − id against Eigen's matrix exponential; both phase functions against the
// dense backend's eigenbasis; the phases of y on x's eigenvectors against a closed form;
// weights in the eigenbasis against Eigen's eigenvectors; the result exactly skew-Hermitian; a
// non-finite x refused on every rank.
#include <ddb/core/phase_function.h>
#include <ddb/core/skew_hermitian_eigenbasis.h>
#include <ddb/distributed/distributed_backend.h>
#include <ddb/distributed/distributed_eigenbasis.h>
#include <ddb/distributed/distributed_matrix.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "mpi_test_support.h"

namespace ddb {
namespace distributed_eigenbasis_tests {

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

// π_a = Im (Vᴴ y V)_aa: for y = x³ + x/2, which commutes with x, the closed form −θ_a³ + θ_a/2;
// for any y, the dense eigenbasis's; the same bits on every rank.
TEST_P(DistributedEigenbasisTest, DiagonalPhasesAreThoseOfACommutingMatrix) {
  const Eigen::MatrixXcd x = randomSkewHermitian(n(), 38, 1.5),
                         other = randomSkewHermitian(n(), 39, 1.0);
  const Eigen::MatrixXcd y = x * x * x + 0.5 * x;
  DistributedEigenbasis basis;
  ASSERT_TRUE(basis.compute(scattered(x)));
  Eigen::VectorXd pi;
  basis.diagonalPhasesOf(scattered(y), pi);
  const Eigen::VectorXd theta = basis.phases();
  const Eigen::VectorXd closed_form = -theta.array().cube() + 0.5 * theta.array();
  EXPECT_LT((pi - closed_form).cwiseAbs().maxCoeff(), 1e-13);
  basis.diagonalPhasesOf(scattered(other), pi);
  SkewHermitianEigenbasis<Eigen::MatrixXcd> dense;
  ASSERT_TRUE(dense.compute(x));
  Eigen::VectorXd reference;
  dense.diagonalPhasesOf(other, reference);
  EXPECT_LT((pi - reference).cwiseAbs().maxCoeff(), 1e-13);
  Eigen::VectorXd on_rank_zero = pi;
  MPI_Bcast(on_rank_zero.data(), n(), MPI_DOUBLE, 0, grid_.comm());
  EXPECT_TRUE(on_rank_zero == pi);
}

// V [W ∘ (Vᴴ a V)] Vᴴ for a symmetric real W against the same formula with Eigen's
// eigenvectors of −ix (any phases of V's columns give it), out aliasing in; W = 1 gives a;
// refused before weights are set.
TEST_P(DistributedEigenbasisTest, WeightsActInTheEigenbasis) {
  const Eigen::MatrixXcd x = randomSkewHermitian(n(), 40, 2.0),
                         a = randomSkewHermitian(n(), 41, 1.0);
  Eigen::MatrixXd weights(n(), n());  // symmetric, the same on every rank
  for (int b = 0; b < n(); ++b) {
    for (int c = 0; c < n(); ++c)
      weights(c, b) = std::cos(0.3 * (b + c)) + 1.0 / (1 + std::abs(b - c));
  }
  DistributedEigenbasis basis;
  ASSERT_TRUE(basis.compute(scattered(x)));
  DistributedMatrix unweighted;  // no weights yet for this basis
  EXPECT_THROW(basis.applyWeights(scattered(a), unweighted), std::logic_error);
  basis.setWeights(weights);
  DistributedMatrix inout = scattered(a);
  basis.applyWeights(inout, inout);
  const Eigen::MatrixXcd result = inout.gather();
  basis.setWeights(Eigen::MatrixXd::Ones(n(), n()));
  DistributedMatrix identity;
  basis.applyWeights(scattered(a), identity);
  const Eigen::MatrixXcd same = identity.gather();
  if (grid_.rank() == 0) {
    const Eigen::MatrixXcd V = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(
                                   Eigen::MatrixXcd(x * std::complex<double>(0.0, -1.0)))
                                   .eigenvectors();
    const Eigen::MatrixXcd hat = V.adjoint() * a * V;
    const Eigen::MatrixXcd reference =
        V * Eigen::MatrixXcd(hat.cwiseProduct(weights)) * V.adjoint();
    EXPECT_LT(relativeDistance(result, reference), 1e-13);
    EXPECT_TRUE(result == Eigen::MatrixXcd(-result.adjoint())) << "not skew-Hermitian bit for bit";
    EXPECT_LT(relativeDistance(same, a), 1e-13);
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

}  // namespace distributed_eigenbasis_tests
}  // namespace ddb
