// AndersonAcceleration (integrators/solvers/anderson_acceleration.h) on affine fixed points
// p = A p + c, whose solution (I − A)⁻¹c Eigen's LU gives independently. On an affine map
// Anderson mixing of depth ≥ n is GMRES on I − A (Walker and Ni 2011), so it ends in at most
// n + 1 mixed iterations on an n-dimensional space, where the plain iteration contracts at
// A's spectral radius.
#include <ddb/integrators/solvers/anderson_acceleration.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/LU>
#include <complex>

namespace ddb {
namespace anderson_acceleration_tests {

// Iterates p ← mix(p, A p + c) from p = 0 and returns the number of maps applied until the
// residual ‖A p + c − p‖ is below tolerance (or `budget`).
template <class Matrix, class Map>
int iterations(const Map& map, Matrix p, double tolerance, int budget, bool mixed, Matrix& out) {
  AndersonAcceleration<Matrix> anderson;
  Matrix g = p;
  for (int k = 1; k <= budget; ++k) {
    map(p, g);
    if ((g - p).norm() <= tolerance) {
      out = g;
      return k;
    }
    if (mixed) anderson.mix(p, g);
    p = g;
  }
  out = p;
  return budget;
}

// A 2×2 real matrix is the space R⁴; A has the eigenvalues 0.95, 0.9, 0.2, −0.1 in a
// non-orthogonal basis, so the plain iteration needs hundreds of maps.
TEST(AndersonAcceleration, SolvesAnAffineMapOnR4InAtMostSixMaps) {
  Eigen::Matrix4d basis;
  basis << 1, 0.3, -0.2, 0.1, 0.2, 1, 0.4, -0.3, -0.1, 0.5, 1, 0.2, 0.3, -0.2, 0.1, 1;
  const Eigen::Matrix4d A =
      basis * Eigen::Vector4d(0.95, 0.9, 0.2, -0.1).asDiagonal() * basis.inverse();
  const Eigen::Vector4d c(1.0, -2.0, 0.5, 3.0);
  const auto map = [&](const Eigen::MatrixXd& p, Eigen::MatrixXd& out) {
    out = (A * p.reshaped() + c).reshaped(2, 2);
  };
  const Eigen::Vector4d exact = (Eigen::Matrix4d::Identity() - A).partialPivLu().solve(c);
  Eigen::MatrixXd solution;
  const Eigen::MatrixXd start = Eigen::MatrixXd::Zero(2, 2);
  const int mixed = iterations(map, start, 1e-10, 100, true, solution);
  EXPECT_LE(mixed, 6) << mixed;  // n + 1 mixed iterations, and the map measuring the residual
  EXPECT_LT((solution.reshaped() - exact).norm(), 1e-8 * exact.norm());
  const int plain = iterations(map, start, 1e-10, 10000, false, solution);
  EXPECT_GT(plain, 100) << plain;
}

// A real-linear map on complex matrices with the spectrum the symmetric DDB's fixed point
// shows on the fluid (docs/design/architecture.md): one slow direction among fast ones,
// p ↦ 0.95 Re⟨u, p⟩ u + 0.1 B p Bᴴ + c, with ‖u‖_F = 1 and B unitary (Re⟨x, y⟩ = Re tr xᴴy).
// The plain iteration, run to round-off, is the reference; mixing needs ten times fewer maps.
TEST(AndersonAcceleration, RemovesTheSlowDirectionOfARealLinearMapOnComplexMatrices) {
  const int n = 4;
  std::srand(7);
  const Eigen::MatrixXcd B =
      Eigen::HouseholderQR<Eigen::MatrixXcd>(Eigen::MatrixXcd::Random(n, n)).householderQ();
  const Eigen::MatrixXcd u = Eigen::MatrixXcd::Random(n, n).normalized();
  const Eigen::MatrixXcd c = Eigen::MatrixXcd::Random(n, n);
  const auto map = [&](const Eigen::MatrixXcd& p, Eigen::MatrixXcd& out) {
    out = 0.95 * (u.adjoint() * p).trace().real() * u + 0.1 * B * p * B.adjoint() + c;
  };
  const Eigen::MatrixXcd start = Eigen::MatrixXcd::Zero(n, n);
  Eigen::MatrixXcd reference, solution;
  const int plain = iterations(map, start, 1e-13, 100000, false, reference);
  const int mixed = iterations(map, start, 1e-13, 100000, true, solution);
  EXPECT_LT(10 * mixed, plain) << mixed << " mixed, " << plain << " plain";
  EXPECT_LT((solution - reference).norm(), 1e-11 * reference.norm());
}

}  // namespace anderson_acceleration_tests
}  // namespace ddb
