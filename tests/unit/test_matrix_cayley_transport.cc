// The Cayley DDB step's update on the matrix groups (MatrixCayleyTransport) against the
// conjugation it stands for, formed with Eigen's inverse.

#include <ddb/groups/cayley.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/LU>

#include "zeitlin_step_fraction.h"

namespace ddb::test {
namespace matrix_cayley_transport_tests {

using Matrix = Eigen::MatrixXcd;

// One DDB Cayley step equals Uᴴ M U with U = cay(2a) cay(2b), a = hξ(p)/2 and
// b = α[p, a], formed here with Eigen's inverse: the one-product update through the
// certified frozen solution (M − 2[a, p̃]) is that conjugation to rounding.
TEST(MatrixCayleyTransport, TheCertifiedOneProductUpdateIsTheCayleyConjugation) {
  const int n = 24;
  for (double alpha : {0.0, 0.5}) {
    const auto fluid = makeZeitlinFluid(n, alpha);
    Matrix W = randomVorticity(n, 51);
    const double h = zeitlinStepFraction(W, 0.05);
    Ddb<Cayley<SUN>> method(fluid, Cayley<SUN>(), LegendreForm::kHamiltonian);
    int certified = 0;
    for (int k = 0; k < 20; ++k) {
      const Matrix M = W;
      method.advance(W, k * h, h);
      const auto& solver = method.legendreSolver();
      if (solver.frozenSolution() != nullptr) ++certified;
      const Matrix& a = solver.halfStep();
      const Matrix& p = solver.solution();
      const Matrix I = Matrix::Identity(n, n);
      const Matrix b = alpha * (p * a - a * p);
      const Matrix U = (I - a).inverse() * (I + a) * (I - b).inverse() * (I + b);
      EXPECT_LT((W - U.adjoint() * M * U).norm(), 1e-14 * M.norm()) << alpha << " step " << k;
    }
    EXPECT_GE(certified, 15) << alpha;  // the cheap update is the common case
  }
}

}  // namespace matrix_cayley_transport_tests
}  // namespace ddb::test
