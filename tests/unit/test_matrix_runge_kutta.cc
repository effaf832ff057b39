// Lobatto IIIC on the matrix groups, its stage equations solved matrix-free
// (integrators/methods/matrix_free_runge_kutta.h, docs/reference/conventions.md §2 and §4): fitted
// order 4 against the adaptive reference on the Manakov body and on Zeitlin's fluid, the fixed-size
// Lobatto IIIC through so(3) ≅ R³, Newton–Krylov's Jacobian against central differences, and
// a failed solve reported like the others.
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/rigid_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gmock/gmock.h>

#include <iostream>
#include <string>
#include <vector>

#include "order_fit.h"
#include "test_support.h"

namespace ddb::test {
namespace matrix_runge_kutta_tests {

/// The fitted slope of ‖μ_K − μ_K^ref‖ over t ∈ [0, t_end] for the given step counts.
template <class G>
OrderFit lobattoOrder(std::shared_ptr<const LiePoissonSystem<G>> system,
                      const typename G::template Dual<double>& mu0, double t_end,
                      const std::vector<int>& step_counts) {
  using Dual = typename G::template Dual<double>;
  auto finalState = [&](const std::string& name, int steps) {
    auto method = makeMethod<G>(name, system);
    Dual last;
    integrate(*method, mu0, 0.0, t_end / steps, steps,
              [&](long, double, const Dual& mu) { last = mu; });
    return last;
  };
  const Dual reference = finalState("reference", 1);
  std::vector<double> hs, errors;
  for (int steps : step_counts) {
    hs.push_back(t_end / steps);
    errors.push_back((finalState("lobatto3c", steps) - reference).norm());
    std::cout << "h = " << hs.back() << ": error " << errors.back() << "\n";
  }
  return fitOrder(hs, errors, 1e-11);
}

Eigen::MatrixXd manakovState(int n, unsigned seed) {
  Sampler s(seed);
  Eigen::MatrixXd a(n, n);
  for (Eigen::Index i = 0; i < a.size(); ++i) a(i) = s.uniform();
  return a - a.transpose();
}

TEST(Lobatto3cOnMatrixGroups, FittedOrderFourOnTheManakovBodyN4) {
  const Eigen::VectorXd J = Eigen::VectorXd::LinSpaced(4, 0.4, 1.3);
  const OrderFit fit =
      lobattoOrder<SON>(makeManakovBody(J, 0.5), manakovState(4, 11), 2.0, {10, 20, 40, 80, 160});
  std::cout << "Manakov N = 4, alpha = 0.5: slope " << fit.slope << "\n";
  ASSERT_GE(fit.points, 4);
  EXPECT_NEAR(fit.slope, 4.0, 0.25);
}

TEST(Lobatto3cOnMatrixGroups, FittedOrderFourOnTheFluidN8) {
  const OrderFit fit =
      lobattoOrder<SUN>(makeZeitlinFluid(8, 0.5), randomVorticity(8, 1), 1.0, {5, 10, 20, 40, 80});
  std::cout << "fluid N = 8, alpha = 0.5: slope " << fit.slope << "\n";
  ASSERT_GE(fit.points, 4);
  EXPECT_NEAR(fit.slope, 4.0, 0.25);
}

// At N = 3 the Manakov body is the rigid body with 𝕀 = (J₂+J₃, J₁+J₃, J₁+J₂) under
// so(3) ≅ R³ (docs/reference/conventions.md §2): the same vector field, so the fixed-size Lobatto
// IIIC (Levenberg–Marquardt on 9 unknowns) and the matrix-free one give the same steps.
TEST(Lobatto3cOnMatrixGroups, AtN3ReproducesTheFixedSizeLobattoOnTheRigidBody) {
  const Eigen::Vector3d J(0.2, 0.45, 0.7);
  const Eigen::Vector3d inertia(J(1) + J(2), J(0) + J(2), J(0) + J(1));
  for (double alpha : {0.0, 0.5}) {
    auto body = makeMethod<SO3>("lobatto3c", makeRigidBody(inertia, alpha));
    auto manakov = makeMethod<SON>("lobatto3c", makeManakovBody(J, alpha));
    Eigen::Vector3d m = inertia.cwiseProduct(Eigen::Vector3d(0, 0.05, 1));
    Eigen::MatrixXd M = SO3::hat(m);
    double worst = 0.0;
    for (int k = 0; k < 300; ++k) {
      m = body->step(m, 0.1 * k, 0.1);
      manakov->advance(M, 0.1 * k, 0.1);
      worst = std::max(worst, (M - Eigen::MatrixXd(SO3::hat(m))).norm() / M.norm());
    }
    std::cout << "alpha " << alpha << ": worst relative difference " << worst << "\n";
    EXPECT_LT(worst, 1e-12) << "alpha " << alpha;
  }
}

// The Jacobian–vector products Newton–Krylov uses: Df(μ)[v] against central differences of
// the vector field, on the fluid (its Hessian a Poisson solve) and the Manakov body.
TEST(Lobatto3cOnMatrixGroups, VectorFieldDerivativeMatchesCentralDifferences) {
  const auto fluid = makeZeitlinFluid(6, 0.5);
  const Eigen::MatrixXcd W = randomVorticity(6, 3), V = randomVorticity(6, 4);
  MatrixFieldWorkspace<SUN> w;
  w.resize(W);
  Eigen::MatrixXcd f(6, 6), df(6, 6);
  fluid->vectorFieldInto(W, w, f);
  fluid->vectorFieldDerivativeInto(V, w, df);
  const double d = 1e-5;
  const Eigen::MatrixXcd central = (fluid->vectorField(Eigen::MatrixXcd(W + d * V)) -
                                    fluid->vectorField(Eigen::MatrixXcd(W - d * V))) /
                                   (2 * d);
  EXPECT_LT((df - central).norm(), 1e-8 * central.norm());
  EXPECT_LT((f - fluid->vectorField(W)).norm(), 1e-15 * f.norm());

  const auto body = makeManakovBody(Eigen::VectorXd::LinSpaced(5, 0.3, 1.5), 0.7);
  const Eigen::MatrixXd M = manakovState(5, 5), U = manakovState(5, 6);
  MatrixFieldWorkspace<SON> v;
  v.resize(M);
  Eigen::MatrixXd g(5, 5), dg(5, 5);
  body->vectorFieldInto(M, v, g);
  body->vectorFieldDerivativeInto(U, v, dg);
  const Eigen::MatrixXd central_body = (body->vectorField(Eigen::MatrixXd(M + d * U)) -
                                        body->vectorField(Eigen::MatrixXd(M - d * U))) /
                                       (2 * d);
  EXPECT_LT((dg - central_body).norm(), 1e-8 * central_body.norm());
}

// Newton–Krylov from the first iterate and the fixed point solve the same stage equations.
TEST(Lobatto3cOnMatrixGroups, NewtonKrylovAndTheFixedPointAgree) {
  const auto fluid = makeZeitlinFluid(8, 0.5);
  MatrixFreeImplicitRungeKutta<SUN, 3> sweeps(fluid, kLobattoIIIC3), newton(fluid, kLobattoIIIC3);
  newton.setNewtonOnly(true);
  Eigen::MatrixXcd x = randomVorticity(8, 2), y = x;
  for (int k = 0; k < 20; ++k) {
    sweeps.advance(x, 0.05 * k, 0.05);
    newton.advance(y, 0.05 * k, 0.05);
    EXPECT_EQ(newton.fixedPointSweeps(), 0);
    EXPECT_GT(newton.newtonSteps(), 0);
  }
  EXPECT_LT((x - y).norm(), 1e-12 * x.norm());
}

// A solve that does not converge (h = 10 on the Manakov body: far beyond the fixed point's
// contraction, and Newton–Krylov from f(μ) diverges) is a SolveFailure naming the step, t, h
// and the residual, after the observer saw every state before it.
TEST(Lobatto3cOnMatrixGroups, AFailedSolveIsASolveFailureNamingTheStep) {
  const Eigen::VectorXd J = Eigen::VectorXd::LinSpaced(4, 0.4, 1.3);
  auto method = makeMethod<SON>("lobatto3c", makeManakovBody(J, 0.5));
  long seen = 0;
  try {
    integrate(*method, manakovState(4, 11), 0.0, 10.0, 5,
              [&](long k, double, const auto&) { seen = k + 1; });
    FAIL() << "no SolveFailure";
  } catch (const SolveFailure& failure) {
    EXPECT_EQ(seen, 1);
    EXPECT_EQ(failure.step(), 0);
    EXPECT_EQ(failure.h(), 10.0);
    EXPECT_GT(failure.residual(), failure.tolerance());
    EXPECT_THAT(failure.what(), ::testing::HasSubstr("Runge-Kutta stage equations (matrix-free"));
    EXPECT_THAT(failure.what(), ::testing::HasSubstr("at step 0 (t = 0, h = 10)"));
  }
}

}  // namespace matrix_runge_kutta_tests
}  // namespace ddb::test
