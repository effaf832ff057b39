// A step of any method on a matrix group allocates nothing once its workspaces exist
// (docs/reference/conventions.md §4): every malloc of this binary is counted
// (tools/malloc_counter.h).
#include <ddb/groups/special_euclidean.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/strang_splitting.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_forcing.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <ddb/systems/zeitlin_viscosity.h>
#include <gtest/gtest.h>

#include <string>

#include "malloc_counter.h"

namespace ddb::test {
namespace {

template <class G>
long allocationsPerStep(std::shared_ptr<const LiePoissonSystem<G>> system,
                        typename G::template Dual<double> mu, double h,
                        const std::string& name = "ddb-cay") {
  auto method = makeMethod<G>(name, system);
  method->advance(mu, 0.0, h);  // first step: workspaces sized
  method->advance(mu, h, h);    // warm start in place
  const long before = tools::mallocCount();
  for (int k = 2; k < 22; ++k) method->advance(mu, k * h, h);
  return (tools::mallocCount() - before) / 20;
}

TEST(Allocations, DdbCayleyOnSuNAllocatesNothingPerStep) {
  for (double alpha : {0.0, 0.5}) {
    EXPECT_EQ(allocationsPerStep<SUN>(makeZeitlinFluid(16, alpha), randomVorticity(16, 1), 0.01), 0)
        << alpha;
  }
}

TEST(Allocations, DdbCayleyOnSoNAllocatesNothingPerStep) {
  Eigen::VectorXd J(5);
  J << 0.3, 0.5, 0.8, 1.1, 1.7;
  Eigen::MatrixXd M = Eigen::MatrixXd::Random(5, 5);
  M = SON::vee(M);
  EXPECT_EQ(allocationsPerStep<SON>(makeManakovBody(J, 0.5), M, 0.05), 0);
}

// Lobatto IIIC's matrix-free stage solver, on its fixed-point path and forced onto
// Newton–Krylov (whose GMRES basis is sized at the first step).
TEST(Allocations, Lobatto3cOnSuNAndSoNAllocatesNothingPerStep) {
  Eigen::VectorXd J(5);
  J << 0.3, 0.5, 0.8, 1.1, 1.7;
  const Eigen::MatrixXd M = SON::vee(Eigen::MatrixXd(Eigen::MatrixXd::Random(5, 5)));
  EXPECT_EQ(
      allocationsPerStep<SUN>(makeZeitlinFluid(16, 0.5), randomVorticity(16, 1), 0.01, "lobatto3c"),
      0);
  EXPECT_EQ(allocationsPerStep<SON>(makeManakovBody(J, 0.5), M, 0.05, "lobatto3c"), 0);
  MatrixFreeImplicitRungeKutta<SON, 3> newton(makeManakovBody(J, 0.5), kLobattoIIIC3);
  newton.setNewtonOnly(true);
  Eigen::MatrixXd mu = M;
  newton.advance(mu, 0.0, 0.05);
  const long before = tools::mallocCount();
  for (int k = 1; k < 11; ++k) newton.advance(mu, k * 0.05, 0.05);
  EXPECT_GT(newton.newtonSteps(), 0);
  EXPECT_EQ(tools::mallocCount() - before, 0);
}

// Every matrix-group method of the table steps without allocating once warmed up, as
// OneStepMethod::advance's comment says: the DDB family with either retraction (the
// exponential's eigendecompositions through LAPACK's ?heevd with kept workspaces; Eigen's
// eigensolver, the fallback without LAPACK, allocates), RK4, Lobatto IIIC and the reference
// (odeint's stepper states are sized once); on the magnetic fluid every method that runs there,
// the exponential ones through the dual numbers' eigenbasis (core/dual_eigenbasis.h).
TEST(Allocations, EveryMatrixGroupMethodStepsWithoutAllocating) {
  Eigen::VectorXd J(5);
  J << 0.3, 0.5, 0.8, 1.1, 1.7;
  const Eigen::MatrixXd M = SON::vee(Eigen::MatrixXd(Eigen::MatrixXd::Random(5, 5)));
  const auto mhd = makeZeitlinMhd(16, 0.5);
  const DualMatrix<Eigen::MatrixXcd> mu =
      zeitlinMhdState(randomVorticity(16, 1), 0.05 * randomVorticity(16, 2));
  for (const MethodInfo& info : kMethods) {
    if ((info.groups & kMatrixGroups) == 0) continue;
#ifndef DDB_USE_LAPACK
    const MethodInfo& recipe =
        info.kind == MethodKind::kComposition ? *findMethod(info.base) : info;
    if (recipe.retraction == RetractionKind::kExponential ||
        recipe.retraction == RetractionKind::kTruncatedExponential2) {
      continue;
    }
#endif
    const std::string name(info.name);
    EXPECT_EQ(
        allocationsPerStep<SUN>(makeZeitlinFluid(16, 0.5), randomVorticity(16, 1), 0.01, name), 0)
        << name;
    EXPECT_EQ(allocationsPerStep<SON>(makeManakovBody(J, 0.5), M, 0.05, name), 0) << name;
    if (methodApplies(info, *mhd)) {
      EXPECT_EQ(allocationsPerStep<DualNumberSUN>(mhd, mu, 0.01, name), 0) << name << ", MHD";
    }
  }
}

// A damped and forced step on a rotating sphere: ddb-cay Strang-split with the viscous flow (its
// transform's workspace sized once, SphericalHarmonicBasis::Workspace) and then with the
// stochastic forcing (its band's harmonics kept, its normals a function of the count).
TEST(Allocations, AViscousAndForcedStepAllocatesNothing) {
  ZeitlinPhysics physics;
  physics.rotation = 1.3;
  const auto fluid = makeZeitlinFluid(16, 0.5, physics);
  const auto& hamiltonian = dynamic_cast<const ZeitlinHamiltonian&>(fluid->hamiltonian());
  ZeitlinViscosity viscosity;
  viscosity.viscosity = 1e-3;
  viscosity.order = 2;
  viscosity.drag = 0.01;
  ZeitlinStochasticForcing forcing;
  forcing.band_centre = 5;
  forcing.band_half_width = 2;
  forcing.rate = 0.1;
  auto damped = std::make_unique<StrangSplitting<SUN>>(
      makeMethod<SUN>("ddb-cay", fluid),
      std::make_unique<ZeitlinViscousFlow>(16, viscosity, hamiltonian.planetaryVorticity()));
  StrangSplitting<SUN> method(std::move(damped),
                              std::make_unique<ZeitlinStochasticForcingFlow>(16, forcing));
  Eigen::MatrixXcd Q = randomVorticity(16, 1) + hamiltonian.planetaryVorticity();
  method.advance(Q, 0.0, 0.01);
  method.advance(Q, 0.01, 0.01);
  const long before = tools::mallocCount();
  for (int k = 2; k < 22; ++k) method.advance(Q, k * 0.01, 0.01);
  EXPECT_EQ(tools::mallocCount() - before, 0);
}

// The exponential methods' injectivity guard (integrators/solvers/injectivity_guard.h) asks the
// group's adRadius before and after every Legendre solve. On SpecialOrthogonal<N>, and through it
// SpecialEuclidean<N>, that is an eigensolver, which works in fixed-capacity storage up to N = 16
// (core/detail/normal_matrix_functions.h); at dynamic size it took 6 mallocs a call.
TEST(Allocations, TheInjectivityGuardsRadiusOnSoNAndSeNAllocatesNothing) {
  const SpecialOrthogonal<4>::Algebra<double> x4 = SpecialOrthogonal<4>::Algebra<double>::Random();
  const SpecialOrthogonal<9>::Algebra<double> x9 = SpecialOrthogonal<9>::Algebra<double>::Random();
  const SpecialEuclidean<4>::Algebra<double> y4 = SpecialEuclidean<4>::Algebra<double>::Random();
  const long before = tools::mallocCount();
  const double radii = SpecialOrthogonal<4>::adRadius(x4) + SpecialOrthogonal<9>::adRadius(x9) +
                       SpecialEuclidean<4>::adRadius(y4);
  EXPECT_EQ(tools::mallocCount() - before, 0);
  EXPECT_GT(radii, 0.0);
}

TEST(Allocations, TheCounterSeesAnAllocation) {
  const long before = tools::mallocCount();
  // Zero(): GCC may make the storage's malloc and zeroing one calloc, which counts too.
  auto* p = new Eigen::MatrixXcd(Eigen::MatrixXcd::Zero(4, 4));
  delete p;
  EXPECT_GE(tools::mallocCount() - before, 2);  // the object and its storage
}

}  // namespace
}  // namespace ddb::test
