// The exponential retraction on SO(N) and SU(N) (docs/reference/conventions.md §1, "Matrix
// algebras"), each piece against something it did not use: the closed forms in x's eigenbasis
// against LieGroupBase's Bernoulli series summed to round-off and Eigen's MatrixFunctions
// exponential; the in-place conjugations against Uᴴ μ U with U formed by Eigen; the DDB
// methods on the Manakov body at N = 3 against the rigid body on SO(3), whose closed forms
// are Rodrigues' (groups/so3.h); the injectivity limit.
#include <ddb/core/skew_hermitian_eigenbasis.h>
#include <ddb/integrators/matrix_kernels/matrix_retraction.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/rigid_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <iostream>
#include <limits>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

#include "test_support.h"

namespace ddb::test {
namespace matrix_exponential_tests {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// A random skew-Hermitian (G = SUN) or skew-symmetric (SON) n×n matrix of Frobenius norm `size`.
template <class G>
typename G::template Algebra<double> randomAlgebra(Eigen::Index n, double size, unsigned seed) {
  using A = typename G::template Algebra<double>;
  std::srand(seed);
  A x = A::Random(n, n);
  x = G::vee(x);
  return A(x * (size / x.norm()));
}

template <class G>
class MatrixExponential : public ::testing::Test {};
using MatrixGroups = ::testing::Types<SON, SUN>;
TYPED_TEST_SUITE(MatrixExponential, MatrixGroups);

TYPED_TEST(MatrixExponential, ClosedFormsAgreeWithTheSeriesSummedToRoundOff) {
  using G = TypeParam;
  using Base = LieGroupBase<G>;
  for (double size : {1e-3, 0.3, 1.0, 2.5}) {
    const auto x = randomAlgebra<G>(5, size, 1);
    const auto y = randomAlgebra<G>(5, 1.0, 2);
    const double tolerance = 1e-14 * (1.0 + size * size);
    EXPECT_LT((G::dexp(x, y) - Base::dexp(x, y)).norm(), tolerance) << size;
    EXPECT_LT((G::dexpInv(x, y) - Base::dexpInv(x, y)).norm(), tolerance) << size;
    EXPECT_LT((G::dexpInvDual(x, y) - Base::dexpInvDual(x, y)).norm(), tolerance) << size;
    EXPECT_LT((G::dexp(x, G::dexpInv(x, y)) - y).norm(), tolerance) << size;
  }
}

TYPED_TEST(MatrixExponential, ExpIsEigensMatrixExponentialAndUnitary) {
  using G = TypeParam;
  for (double size : {1e-6, 0.5, 3.0, 10.0}) {
    const auto x = randomAlgebra<G>(6, size, 3);
    const auto g = G::exp(x);
    using M = std::decay_t<decltype(g)>;
    const M expected = x.exp();
    EXPECT_LT((g - expected).norm(), 4e-15 * (1.0 + size)) << size;
    EXPECT_LT((g.adjoint() * g - M::Identity(6, 6)).norm(), 10 * 6 * kEpsilon) << size;
  }
}

TYPED_TEST(MatrixExponential, AdRadiusIsTheSpreadOfTheEigenphases) {
  using G = TypeParam;
  const auto x = randomAlgebra<G>(5, 2.0, 4);
  // The eigenvalues of ad_x = [x, ·] on gl(N) by Eigen's dense eigensolver.
  const Eigen::Index n = x.rows();
  Eigen::MatrixXcd ad(n * n, n * n);
  Eigen::MatrixXcd unit = Eigen::MatrixXcd::Zero(n, n);
  const Eigen::MatrixXcd xc = x.template cast<std::complex<double>>();
  for (Eigen::Index k = 0; k < n * n; ++k) {
    unit.data()[k] = 1.0;
    ad.col(k) = (xc * unit - unit * xc).reshaped();
    unit.data()[k] = 0.0;
  }
  const double radius = ad.eigenvalues().cwiseAbs().maxCoeff();
  EXPECT_NEAR(G::adRadius(x), radius, 1e-13 * radius);
}

// Ad*_{τ(x)} μ = τ(x)ᴴ μ τ(x) with τ formed by Eigen: cay(x) = (I − x/2)⁻¹(I + x/2), exp by
// MatrixFunctions.
TYPED_TEST(MatrixExponential, InPlaceConjugationsAreTheFormedOnes) {
  using G = TypeParam;
  using D = typename G::template Dual<double>;
  const D mu = randomAlgebra<G>(6, 3.0, 5);
  for (double size : {1e-9, 0.4, 2.0}) {
    const D x = randomAlgebra<G>(6, size, 6);
    const D I = D::Identity(6, 6);
    const D cay = (I - 0.5 * x).inverse() * (I + 0.5 * x);
    const D ex = x.exp();
    D by_cayley = mu, by_exp = mu;
    MatrixConjugation<Cayley<G>> cayley;
    cayley.prepare(x);
    cayley.apply(by_cayley);
    MatrixConjugation<Exponential<G>> exponential;
    exponential.prepare(x);
    exponential.apply(by_exp);
    EXPECT_LT((by_cayley - cay.adjoint() * mu * cay).norm(), 1e-14 * mu.norm()) << size;
    EXPECT_LT((by_exp - ex.adjoint() * mu * ex).norm(), 1e-14 * mu.norm()) << size;
  }
}

// The Manakov body at N = 3 is the rigid body with 𝕀 = (J₂+J₃, J₁+J₃, J₁+J₂)
// (docs/reference/conventions.md §2): every DDB-family method on SO(N), through the eigenbasis, and
// on SO(3), through Rodrigues' formulas and the small-group solver, agree over 300 steps to
// what the solvers' tolerance allows.
TEST(ManakovBody, AtN3EveryDdbMethodReproducesTheRigidBody) {
  const Eigen::Vector3d J(0.2, 0.45, 0.7);
  const Eigen::Vector3d inertia(J(1) + J(2), J(0) + J(2), J(0) + J(1));
  for (double alpha : {0.0, 0.5}) {
    const auto body = makeRigidBody(inertia, alpha);
    const auto manakov = makeManakovBody(J, alpha);
    for (const MethodInfo& info : kMethods) {
      if (!info.keeps_casimirs || !methodApplies(info, *manakov)) continue;
      auto on_so3 = makeMethod<SO3>(info, body);
      auto on_son = makeMethod<SON>(info, manakov);
      Eigen::Vector3d m = inertia.cwiseProduct(Eigen::Vector3d(0, 0.05, 1));
      Eigen::MatrixXd M = SO3::hat(m);
      double worst = 0.0;
      for (int k = 0; k < 300; ++k) {
        on_so3->advance(m, 0.1 * k, 0.1);
        on_son->advance(M, 0.1 * k, 0.1);
        worst = std::max(worst, (M - Eigen::MatrixXd(SO3::hat(m))).norm() / M.norm());
      }
      // Each Legendre solve on either side is exact to its relative tolerance, 1e-14: the
      // two trajectories may part by that much per solve.
      const int stages = info.scheme == SchemeKind::kYoshida6     ? 7
                         : info.scheme == SchemeKind::kTripleJump ? 3
                                                                  : 1;
      std::cout << info.name << " alpha " << alpha << ": " << worst << "\n";
      EXPECT_LT(worst, 300 * stages * 1e-14) << info.name << " alpha " << alpha;
    }
  }
}

// Each step on the fluid solves its defining equations (docs/reference/conventions.md §2), checked
// with the series (dexp⁻¹)* summed to round-off, Eigen's exp and Eigen's inverse:
//   DDB:  M_k = (dτ⁻¹_{hξ})* p,  M_{k+1} = Ad*_{τ(hξ) τ(hφ)} M_k;
//   symmetric DDB:  (dτ⁻¹_{hξ})* p = Ad*_{τ(hφ/2)} M_k,  M_{k+1} = Ad*_{τ(hφ/2) τ(hξ) τ(hφ/2)} M_k,
// with ξ = ∂H/∂μ(p) and φ = α[p, ξ] (K = α·Id).
template <template <class> class Method, class R>
void checkDefiningEquations(bool symmetric, int truncation = -1) {
  using D = Eigen::MatrixXcd;
  const double alpha = 0.5, h = 0.05;
  const auto fluid = makeZeitlinFluid(6, alpha);
  Method<R> method(fluid, R(), LegendreForm::kHamiltonian);
  const D I = D::Identity(6, 6);
  const auto tau = [&](const D& x) -> D {
    if constexpr (std::is_same_v<R, Cayley<SUN>>) {
      return (I - 0.5 * x).inverse() * (I + 0.5 * x);
    } else {
      return x.exp();
    }
  };
  const auto dualOfInverseTangent = [&](const D& x, const D& p) -> D {
    if constexpr (std::is_same_v<R, Cayley<SUN>>) {
      return (I + 0.5 * x) * p * (I - 0.5 * x);
    } else {
      return truncation < 0 ? LieGroupBase<SUN>::dexpInvDual(x, p)
                            : LieGroupBase<SUN>::dexpInvDualSeries(x, p, truncation);
    }
  };
  D M = randomVorticity(6, 1);
  for (int k = 0; k < 20; ++k) {
    const D before = M;
    method.advance(M, k * h, h);
    const D& p = method.legendreSolver().solution();
    const D xi = fluid->velocity(p);
    const D phi = alpha * (p * xi - xi * p);
    const D lhs = dualOfInverseTangent(h * xi, p);
    const D kick = tau(0.5 * h * phi);
    const D target = symmetric ? D(kick.adjoint() * before * kick) : before;
    EXPECT_LT((lhs - target).norm(), 1e-13 * before.norm()) << method.name() << " step " << k;
    const D U = symmetric ? D(kick * tau(h * xi) * kick) : D(tau(h * xi) * tau(h * phi));
    EXPECT_LT((M - U.adjoint() * before * U).norm(), 1e-13 * before.norm())
        << method.name() << " step " << k;
  }
}

TEST(MatrixExponential, EachStepOnTheFluidSolvesItsDefiningEquations) {
  checkDefiningEquations<Ddb, Exponential<SUN>>(false);
  checkDefiningEquations<Ddb, TruncatedExponential<SUN>>(false, 2);
  checkDefiningEquations<SymmetricDdb, Exponential<SUN>>(true);
  checkDefiningEquations<SymmetricDdb, Cayley<SUN>>(true);
}

// At small h the first sweep of the exp fixed point already lands at rounding level, and the
// next ones stall there (no contraction to measure): the solve accepts the iterate whose
// update, its residual, is within the tolerance, as Cayley's Newton check does. (It failed
// at step 486 of this run with residual 1.2e-14 < tolerance 4e-14 before.)
TEST(MatrixExponential, SweepsStalledAtRoundingAreAcceptedWithinTheTolerance) {
  const auto fluid = makeZeitlinFluid(16, 0.5);
  for (const char* name : {"ddb-exp-exact", "ddb-exp"}) {
    auto method = makeMethod<SUN>(name, fluid);
    long steps = 0;
    EXPECT_NO_THROW(integrate(*method, randomVorticity(16, 1), 0.0, 0.005, 800,
                              [&](long k, double, const auto&) { steps = k; }))
        << name;
    EXPECT_EQ(steps, 800) << name;
  }
}

// A step whose solution has h·adRadius(ξ) ≥ π is refused with InjectivityLimit, which names
// the largest admissible h, and integrate() keeps the states before it. At h = 1.2π/adRadius
// of the initial ξ the DDB fixed point fails at step 0; the symmetric DDB's mixed sweeps
// (AndersonAcceleration) find solutions on the principal branch for a few steps and are
// refused later: every step taken must have its solution inside the limit, by Eigen's
// eigenvalues of iξ (adRadius = their spread), and a refusal must come within 5 steps.
TEST(MatrixExponential, StepsPastTheInjectivityLimitAreRefused) {
  const auto fluid = makeZeitlinFluid(6, 0.0);
  const Eigen::MatrixXcd W0 = randomVorticity(6, 2);
  const double radius = SUN::adRadius(Eigen::MatrixXcd(fluid->velocity(W0)));
  const double h = 1.2 * M_PI / radius;
  const auto spread = [](const Eigen::MatrixXcd& xi) {
    const Eigen::MatrixXcd hermitian = std::complex<double>(0, 1) * xi;
    const Eigen::VectorXd theta =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(hermitian).eigenvalues();
    return theta.maxCoeff() - theta.minCoeff();
  };
  for (const char* name : {"ddb-exp-exact", "ddb-exp", "sddb-exp"}) {
    auto method = makeMethod<SUN>(name, fluid);
    const auto* legendre = dynamic_cast<const LegendreMethod<Exponential<SUN>>*>(method.get());
    const auto* truncated =
        dynamic_cast<const LegendreMethod<TruncatedExponential<SUN>>*>(method.get());
    long seen = 0;
    try {
      integrate(*method, W0, 0.0, h, 5, [&](long k, double, const auto&) {
        ++seen;
        if (k == 0) return;
        const Eigen::MatrixXcd& p = legendre != nullptr ? legendre->legendreSolver().solution()
                                                        : truncated->legendreSolver().solution();
        EXPECT_LT(h * spread(fluid->velocity(p)), M_PI) << name << " step " << k;
      });
      ADD_FAILURE() << name << " stepped past the limit";
    } catch (const InjectivityLimit& e) {
      EXPECT_EQ(seen, e.step() + 1) << name;
      EXPECT_GT(e.largestH(), 0.0) << name;
      EXPECT_LT(e.largestH(), h) << name;
    } catch (const SolveFailure& e) {
      // A sweep started past the limit need not contract: a failed solve.
      EXPECT_EQ(seen, e.step() + 1) << name << ": " << e.what();
    }
  }
}

}  // namespace matrix_exponential_tests
}  // namespace ddb::test
