// Integrators on the rigid body of Scenario A (docs/reference/conventions.md §3): orders fitted
// against the reference solver, exact Casimir preservation of DDB, agreement of its two
// forms, the reference against itself, and a failed solve keeping the prefix.
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>
#include <gmock/gmock.h>

#include <array>
#include <cmath>
#include <typeinfo>

#include "order_fit.h"
#include "test_support.h"

namespace ddb::test {
namespace integrators_tests {

const RigidBodyScenario& kA = rigidBodyScenario("A");
const Eigen::Vector3d kInertia = kA.inertia;
const Eigen::Vector3d kOmega0 = kA.omega0;
const Eigen::Vector3d kM0 = kA.mu0();

Eigen::Vector3d finalState(OneStepMethod<SO3>& method, double h, double t_end) {
  Eigen::Vector3d last;
  const long steps = std::lround(t_end / h);
  integrate(method, kM0, 0.0, h, steps,
            [&](long, double, const Eigen::Vector3d& mu) { last = mu; });
  return last;
}

Eigen::Vector3d referenceState(double alpha, double t_end, double tolerance = 1e-13) {
  ReferenceSolver<SO3> reference(makeRigidBody(kInertia, alpha), tolerance);
  return finalState(reference, 0.5, t_end);
}

struct OrderCase {
  std::string method;
  double alpha;
  std::vector<double> hs;
};

std::unique_ptr<OneStepMethod<SO3>> makeMethod(const std::string& name, double alpha) {
  return ddb::makeMethod<SO3>(name, makeRigidBody(kInertia, alpha));
}

class OrderTest : public ::testing::TestWithParam<OrderCase> {};

TEST_P(OrderTest, FittedSlopeMatchesTheoreticalOrder) {
  const OrderCase& c = GetParam();
  const double t_end = 10.0;
  const Eigen::Vector3d reference = referenceState(c.alpha, t_end);
  std::vector<double> errors;
  for (double h : c.hs) {
    auto method = makeMethod(c.method, c.alpha);
    errors.push_back((finalState(*method, h, t_end) - reference).norm());
  }
  const OrderFit fit = fitOrder(c.hs, errors);
  ASSERT_GE(fit.points, 4) << "too few step sizes above the round-off plateau";
  // The order the method table claims (integrators/methods/method_table.h).
  const MethodInfo& info = *findMethod(c.method);
  const double expected = c.alpha == 0.0 ? info.order_without_dissipation : info.order;
  EXPECT_NEAR(fit.slope, expected, 0.25) << c.method << " alpha " << c.alpha;
  RecordProperty("slope", std::to_string(fit.slope));
  std::cout << c.method << " alpha=" << c.alpha << " slope=" << fit.slope << "\n";
}

const std::vector<double> kDdbSteps{0.1, 0.05, 0.025, 0.0125, 0.00625};
// ddb-cay-implicit's first-order term is small beside its second-order one down to h = 0.0125:
// its slope is fitted below that (docs/reference/conventions.md §2, "Orders and their tests").
const std::vector<double> kSmallDdbSteps{0.0125, 0.00625, 0.003125, 0.0015625, 0.00078125};
const std::vector<double> kRkSteps{0.2, 0.1, 0.05, 0.025, 0.0125};
const std::vector<double> kSixthOrderSteps{0.5, 0.4, 0.25, 0.2, 0.125};  // divide t_end

/// Every fixed-step row of the method table without dissipation (α = 0), so that a new row
/// gets its order_without_dissipation fitted; with α = 0.5 the DDB steps and the Runge–Kutta
/// methods here, the symmetric and composed rows in test_symmetric.cc.
std::vector<OrderCase> orderCases() {
  std::vector<OrderCase> cases{
      {"ddb-cay", 0.5, kDdbSteps},          {"ddb-exp", 0.5, kDdbSteps},
      {"ddb-exp-exact", 0.5, kDdbSteps},    {"ddb-cay-implicit", 0.5, kSmallDdbSteps},
      {"ddb-exp-implicit", 0.5, kDdbSteps}, {"rk4", 0.5, kRkSteps},
      {"lobatto3c", 0.5, kRkSteps}};
  for (const MethodInfo& m : kMethods) {
    if ((m.groups & kFixedSizeGroups) == 0 || m.kind == MethodKind::kReference) continue;
    const int order = m.order_without_dissipation;
    cases.push_back({std::string(m.name), 0.0,
                     order <= 2   ? kDdbSteps
                     : order <= 4 ? kRkSteps
                                  : kSixthOrderSteps});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(ScenarioA, OrderTest, ::testing::ValuesIn(orderCases()),
                         [](const auto& info) {
                           std::string name =
                               info.param.method + "_alpha" + (info.param.alpha > 0 ? "05" : "0");
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

TEST(Ddb, KeepsCasimirOverTenThousandSteps) {
  auto body = makeRigidBody(kInertia, 0.5);
  std::vector<std::unique_ptr<OneStepMethod<SO3>>> methods;
  for (LegendreForm form : {LegendreForm::kLagrangian, LegendreForm::kHamiltonian}) {
    methods.push_back(std::make_unique<Ddb<Cayley<SO3>>>(body, Cayley<SO3>(), form));
    methods.push_back(
        std::make_unique<Ddb<TruncatedExponential<SO3>>>(body, TruncatedExponential<SO3>(2), form));
    methods.push_back(std::make_unique<Ddb<Exponential<SO3>>>(body, Exponential<SO3>(), form));
  }
  const double c0 = kM0.norm();
  for (auto& method : methods) {
    double drift = 0.0;
    integrate(*method, kM0, 0.0, 0.1, 10000, [&](long, double, const Eigen::Vector3d& mu) {
      drift = std::max(drift, std::abs(mu.norm() - c0) / c0);
    });
    EXPECT_LE(drift, 1e-13) << method->name();
    std::cout << method->name() << " max relative Casimir drift " << drift << "\n";
  }
}

TEST(Ddb, LagrangianAndHamiltonianFormsAgree) {
  // Without sweeps (they work in p in both forms), so that Newton solves each form in its own
  // unknown: ξ with l's derivatives, p with H's.
  auto body = makeRigidBody(kInertia, 0.5);
  SolverOptions newton;
  newton.max_sweeps = 0;
  Ddb<Cayley<SO3>> lagrangian(body, Cayley<SO3>(), LegendreForm::kLagrangian, newton);
  Ddb<Cayley<SO3>> hamiltonian(body, Cayley<SO3>(), LegendreForm::kHamiltonian, newton);
  Ddb<Exponential<SO3>> lagrangian_exp(body, Exponential<SO3>(), LegendreForm::kLagrangian, newton);
  Ddb<Exponential<SO3>> hamiltonian_exp(body, Exponential<SO3>(), LegendreForm::kHamiltonian,
                                        newton);
  EXPECT_LT((finalState(lagrangian, 0.1, 30.0) - finalState(hamiltonian, 0.1, 30.0)).norm(), 1e-12);
  EXPECT_LT((finalState(lagrangian_exp, 0.1, 30.0) - finalState(hamiltonian_exp, 0.1, 30.0)).norm(),
            1e-12);
}

TEST(Ddb, FirstStepSolvesTheDiscreteLegendreEquation) {
  // Independent check of one step for Cayley on SO(3): with ξ from the step, the
  // paper's closed form (dcay^{-1}_{hξ})* = I + hξ̂/2 + h²ξξᵀ/4 maps 𝕀ξ back to M_0,
  // and M_1 = (cay(hξ) cay(hφ))ᵀ M_0 with φ = α 𝕀ξ × ξ.
  const double h = 0.1, alpha = 0.5;
  auto body = makeRigidBody(kInertia, alpha);
  Ddb<Cayley<SO3>> ddb(body);
  const Eigen::Vector3d M1 = ddb.step(kM0, 0.0, h);
  // Solve for ξ by a plain fixed-point iteration ξ = 𝕀^{-1}(I + hξ̂/2 + h²ξξᵀ/4)^{-1} M_0.
  Eigen::Vector3d xi = kOmega0;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Matrix3d A =
        Eigen::Matrix3d::Identity() + h * SO3::hat(xi) / 2 + h * h * xi * xi.transpose() / 4;
    xi = (A.inverse() * kM0).cwiseQuotient(kInertia);
  }
  auto cay = [](const Eigen::Vector3d& x) {
    const Eigen::Matrix3d X = SO3::hat(x);
    return Eigen::Matrix3d((Eigen::Matrix3d::Identity() - X / 2).inverse() *
                           (Eigen::Matrix3d::Identity() + X / 2));
  };
  const Eigen::Vector3d phi = alpha * kInertia.cwiseProduct(xi).cross(xi);
  const Eigen::Vector3d expected = (cay(h * xi) * cay(h * phi)).transpose() * kM0;
  EXPECT_LT((M1 - expected).norm(), 1e-14);
}

TEST(Reference, AgreesWithItselfAtTighterTolerance) {
  auto body = makeRigidBody(kInertia, 0.5);
  ReferenceSolver<SO3> loose(body, 1e-12), tight(body, 1e-13);
  Trajectory<SO3> a, b;
  integrate(loose, kM0, 0.0, 0.1, 300, a.record());
  integrate(tight, kM0, 0.0, 0.1, 300, b.record());
  double worst = 0.0;
  for (size_t k = 0; k < a.states.size(); ++k)
    worst = std::max(worst, (a.states[k] - b.states[k]).norm());
  EXPECT_LT(worst, 1e-10);
}

TEST(Reference, OneLongStepAgreesWithManyShortOnes) {
  // One adaptive sweep over [0, 30] (as the sweeps use) against 300 observed steps.
  auto body = makeRigidBody(kInertia, 0.5);
  ReferenceSolver<SO3> one(body), many(body);
  EXPECT_LT((finalState(one, 30.0, 30.0) - finalState(many, 0.1, 30.0)).norm(), 1e-11);
}

// Energy ascent (α < 0) from near the minimum-energy rotation about e2: |Ω| grows from
// 0.4 towards |M|/𝕀₃ = 1, so at h = 4 an exp step passes the injectivity limit h|ξ| = π
// (docs/reference/guarantees.md §2) after some good steps. Cayley DDB takes every h, so it is not
// the probe here.
const Eigen::Vector3d kNearMinimum(0.05, 0.5, 0.05);
constexpr double kAscent = -0.5;

TEST(Ddb, TooLargeStepThrowsTypedErrorAndKeepsPrefix) {
  auto body = makeRigidBody(kInertia, kAscent);
  Ddb<Exponential<SO3>> ddb(body);
  Trajectory<SO3> trajectory;
  const double h = 4.0;
  try {
    integrate(ddb, kNearMinimum, 0.0, h, 40, trajectory.record());
    FAIL() << "expected SolveFailure";
  } catch (const SolveFailure& failure) {
    EXPECT_GE(failure.step(), 1);
    EXPECT_EQ(static_cast<long>(trajectory.states.size()), failure.step() + 1);
    EXPECT_DOUBLE_EQ(failure.time(), failure.step() * h);
    EXPECT_DOUBLE_EQ(failure.h(), h);
    EXPECT_GT(failure.residual(), failure.tolerance());
    EXPECT_THAT(failure.what(), ::testing::HasSubstr("step " + std::to_string(failure.step())));
    for (const auto& mu : trajectory.states) EXPECT_TRUE(mu.allFinite());
    std::cout << failure.what() << "\n";
  }
}

// The tableau-driven step with its unrolled stage loops is the classical RK4, written out
// here on eq. (3.6), Ṁ = M × Ω + α M × (M × Ω), to a few ulps (the sums are associated
// differently).
TEST(ExplicitRungeKutta, Rk4IsTheClassicalFormulaWrittenOut) {
  const double alpha = 0.5;
  auto body = makeRigidBody(kInertia, alpha);
  ExplicitRungeKutta<SO3, 4> rk4(body, kClassicalRk4);
  const auto field = [&](const Eigen::Vector3d& m) -> Eigen::Vector3d {
    const Eigen::Vector3d omega = m.cwiseQuotient(kInertia);
    return m.cross(omega) + alpha * m.cross(m.cross(omega));
  };
  Sampler s(19);
  for (double h : {0.01, 0.1, 0.7}) {
    for (int i = 0; i < 5; ++i) {
      const Eigen::Vector3d m = s.vector<Eigen::Vector3d>();
      const Eigen::Vector3d k1 = field(m), k2 = field(m + 0.5 * h * k1),
                            k3 = field(m + 0.5 * h * k2), k4 = field(m + h * k3);
      const Eigen::Vector3d expected = m + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      EXPECT_LT((rk4.step(m, 0.0, h) - expected).norm(),
                8 * std::numeric_limits<double>::epsilon() * expected.norm())
          << "h " << h;
    }
  }
}

// rk4's step through the system's own sweep (LiePoissonSystem::explicitStep): a system of
// makeLiePoissonSystem compiles it with its field inlined, one built by LiePoissonSystem's own
// constructor evaluates each stage through the base classes' virtual calls. The same
// operations in the same order, so the same bits at every step, on SO(3) and SE(3).
template <class G>
void expectTheSameRk4Bits(std::shared_ptr<const LiePoissonSystem<G>> typed,
                          std::shared_ptr<const LiePoissonSystem<G>> generic,
                          const typename G::template Dual<double>& mu0, double h) {
  const LiePoissonSystem<G>& fast_system = *typed;
  const LiePoissonSystem<G>& plain_system = *generic;
  ASSERT_NE(typeid(fast_system), typeid(LiePoissonSystem<G>));  // a TypedLiePoissonSystem
  ASSERT_EQ(typeid(plain_system), typeid(LiePoissonSystem<G>));
  ExplicitRungeKutta<G, 4> fast(typed, kClassicalRk4), plain(generic, kClassicalRk4);
  typename G::template Dual<double> a = mu0, b = mu0;
  for (int k = 0; k < 500; ++k) {
    fast.advance(a, k * h, h);
    plain.advance(b, k * h, h);
    ASSERT_TRUE((a.array() == b.array()).all()) << "step " << k;
  }
  EXPECT_GT((a - mu0).norm(), 0.1);  // the states moved
}

TEST(ExplicitRungeKutta, TheTypedSystemsStepIsTheGenericSweepToTheBit) {
  const double alpha = 0.5;
  expectTheSameRk4Bits<SO3>(makeRigidBody(kInertia, alpha),
                            std::make_shared<const LiePoissonSystem<SO3>>(
                                "generic", std::make_shared<const RigidBodyHamiltonian>(kInertia),
                                std::make_shared<const ScaledIdentityMetric<SO3>>(alpha)),
                            kM0, 0.1);
  const HeavyTopSetup top;
  expectTheSameRk4Bits<SE3>(
      top.system(),
      std::make_shared<const LiePoissonSystem<SE3>>(
          "generic", std::make_shared<const HeavyTopHamiltonian>(top.inertia, top.mgl, top.chi),
          std::make_shared<const DiagonalMetric<SE3>>(top.alpha, top.metric)),
      top.mu0, 0.05);
}

// A tableau of other than four stages takes the same sweep with the field through
// vectorFieldInto: Kutta's third-order method (Hairer, Nørsett, Wanner I, II.1, Table 1.1),
// its order fitted against the reference solver.
TEST(ExplicitRungeKutta, KuttasThreeStageTableauHasOrderThree) {
  const ButcherTableau<3> kutta{"kutta3",
                                {{{0.0, 0.0, 0.0}, {0.5, 0.0, 0.0}, {-1.0, 2.0, 0.0}}},
                                {1.0 / 6, 2.0 / 3, 1.0 / 6},
                                {0.0, 0.5, 1.0}};
  const double alpha = 0.5, t_end = 10.0;
  const Eigen::Vector3d reference = referenceState(alpha, t_end);
  std::vector<double> errors;
  for (double h : kRkSteps) {
    ExplicitRungeKutta<SO3, 3> method(makeRigidBody(kInertia, alpha), kutta);
    errors.push_back((finalState(method, h, t_end) - reference).norm());
  }
  const OrderFit fit = fitOrder(kRkSteps, errors);
  ASSERT_GE(fit.points, 4);
  EXPECT_NEAR(fit.slope, 3.0, 0.25);
}

TEST(Integrate, RejectsBadInputNamingIt) {
  auto body = makeRigidBody(kInertia, 0.5);
  ExplicitRungeKutta<SO3, 4> rk4(body, kClassicalRk4);
  auto ignore = [](long, double, const Eigen::Vector3d&) {};
  const Eigen::Vector3d bad(1, NAN, 0);
  EXPECT_THAT([&] { integrate(rk4, bad, 0.0, 0.1, 1, ignore); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("mu0")));
  EXPECT_THAT([&] { integrate(rk4, kM0, 0.0, -0.1, 1, ignore); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("h = -0.1")));
  EXPECT_THAT([&] { integrate(rk4, kM0, 0.0, INFINITY, 1, ignore); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("h = inf")));
}

/// The Butcher order conditions of the rooted trees up to order 4 (Hairer, Nørsett, Wanner I,
/// II.2, Table 2.2), and c = A·1; then the bushy tree of order 5, Σ b c⁴ = 1/5, which both
/// of these tableaus miss (5/24), so their order is exactly 4.
template <int S>
void expectOrderFour(const ButcherTableau<S>& t) {
  std::array<double, S> ac{}, ac2{}, aac{};
  for (int i = 0; i < S; ++i) {
    double row = 0.0;
    for (int j = 0; j < S; ++j) {
      row += t.a[i][j];
      ac[i] += t.a[i][j] * t.c[j];
      ac2[i] += t.a[i][j] * t.c[j] * t.c[j];
    }
    EXPECT_NEAR(t.c[i], row, 1e-15) << t.name << " c_" << i;
  }
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j) aac[i] += t.a[i][j] * ac[j];
  const auto sum = [&](auto term) {
    double total = 0.0;
    for (int i = 0; i < S; ++i) total += t.b[i] * term(i);
    return total;
  };
  const auto c = [&](int i, int p) { return std::pow(t.c[i], p); };
  EXPECT_NEAR(sum([&](int) { return 1.0; }), 1.0, 1e-15) << t.name;
  EXPECT_NEAR(sum([&](int i) { return c(i, 1); }), 1.0 / 2, 1e-15) << t.name;
  EXPECT_NEAR(sum([&](int i) { return c(i, 2); }), 1.0 / 3, 1e-15) << t.name;
  EXPECT_NEAR(sum([&](int i) { return ac[i]; }), 1.0 / 6, 1e-15) << t.name;
  EXPECT_NEAR(sum([&](int i) { return c(i, 3); }), 1.0 / 4, 1e-15) << t.name;
  EXPECT_NEAR(sum([&](int i) { return c(i, 1) * ac[i]; }), 1.0 / 8, 1e-15) << t.name;
  EXPECT_NEAR(sum([&](int i) { return ac2[i]; }), 1.0 / 12, 1e-15) << t.name;
  EXPECT_NEAR(sum([&](int i) { return aac[i]; }), 1.0 / 24, 1e-15) << t.name;
  EXPECT_GT(std::abs(sum([&](int i) { return c(i, 4); }) - 1.0 / 5), 1e-3) << t.name;
}

TEST(ButcherTableau, TableausHaveTheOrderTheMethodTableClaims) {
  ASSERT_EQ(findMethod("rk4")->order, 4);
  ASSERT_EQ(findMethod("lobatto3c")->order, 4);
  expectOrderFour(kClassicalRk4);
  expectOrderFour(kLobattoIIIC3);
  EXPECT_TRUE(kClassicalRk4.isExplicit());
  EXPECT_FALSE(kLobattoIIIC3.isExplicit());
}

TEST(RunMethod, SinkSeesEveryKthStateAndTheLastWithDriftOverAllStates) {
  auto body = makeRigidBody(kInertia, 0.5);
  auto rk4 = ddb::makeMethod<SO3>("rk4", body);
  // Independent expectation: integrate() over every state, the drift computed here.
  Trajectory<SO3> all;
  integrate(*rk4, kM0, 0.0, 0.3, 10, all.record());
  double drift = 0.0;
  for (const auto& mu : all.states) drift = std::max(drift, std::abs(mu.norm() / kM0.norm() - 1));

  RunOptions options;
  options.every = 4;
  std::vector<long> seen;
  const RunResult<SO3> run = runMethod(*rk4, *body, kM0, 0.3, 10, options,
                                       [&](long k, double t, const Eigen::Vector3d& mu) {
                                         seen.push_back(k);
                                         EXPECT_DOUBLE_EQ(t, all.times[k]);
                                         EXPECT_EQ(mu, all.states[k]);
                                       });
  EXPECT_THAT(seen, ::testing::ElementsAre(0, 4, 8, 10));
  EXPECT_TRUE(run.ok());
  EXPECT_EQ(run.steps, 10);
  EXPECT_EQ(run.final, all.states.back());
  EXPECT_NEAR(run.casimir_drift, drift, 1e-16);
  EXPECT_GT(run.casimir_drift, 0.0);  // rk4 does not keep |M|
}

TEST(RunMethod, FailureIsRecordedWithItsStepAndThePrefixReachesTheSink) {
  // ddb-exp-exact cannot take h = 4 for long (Ddb.TooLargeStepThrowsTypedErrorAndKeepsPrefix);
  // integrate() says at which step, runMethod() must report the same without throwing.
  auto body = makeRigidBody(kInertia, kAscent);
  auto method = ddb::makeMethod<SO3>("ddb-exp-exact", body);
  long expected_step = -1;
  try {
    integrate(*method, kNearMinimum, 0.0, 4.0, 40, [](long, double, const Eigen::Vector3d&) {});
  } catch (const SolveFailure& failure) {
    expected_step = failure.step();
  }
  ASSERT_GT(expected_step, 5);
  RunOptions options;
  options.every = 5;
  std::vector<long> seen;
  const RunResult<SO3> run =
      runMethod(*method, *body, kNearMinimum, 4.0, 40, options,
                [&](long k, double, const Eigen::Vector3d&) { seen.push_back(k); });
  std::vector<long> expected_seen;
  for (long k = 0; k <= expected_step; k += 5) expected_seen.push_back(k);
  if (expected_seen.back() != expected_step) expected_seen.push_back(expected_step);
  EXPECT_FALSE(run.ok());
  EXPECT_EQ(run.failed_step, expected_step);
  EXPECT_EQ(run.steps, expected_step);
  EXPECT_DOUBLE_EQ(run.t_final, 4.0 * expected_step);
  EXPECT_EQ(seen, expected_seen);
  EXPECT_THAT(run.failure, ::testing::HasSubstr("step " + std::to_string(expected_step)));
}

TEST(RunMethod, ExpStepPastItsLimitIsAFailureNotAnException) {
  // h = 2 on the heavy top: the exp method's |hξ| reaches π (docs/reference/guarantees.md §2).
  const HeavyTopSetup top;
  auto system = top.system();
  auto method = ddb::makeMethod<SE3>("ddb-exp-exact", system);
  RunResult<SE3> run;
  ASSERT_NO_THROW(run = runMethod(*method, *system, top.mu0, 2.0, 15));
  EXPECT_FALSE(run.ok());
  EXPECT_GE(run.failed_step, 0);
  EXPECT_EQ(run.failed_step, run.steps);
  EXPECT_THAT(run.failure, ::testing::HasSubstr("step " + std::to_string(run.failed_step)));
  // Bad arguments to runMethod itself still throw.
  EXPECT_THROW(runMethod(*method, *system, top.mu0, -1.0, 15), InvalidArgument);
}

// An explicit step that overflows is reported as a non-finite state with its step, t and
// h, not as a solver residual; the observer has seen every state before it.
TEST(Integrate, OverflowIsReportedAsANonFiniteState) {
  auto rk4 = ddb::makeMethod<SO3>("rk4", makeRigidBody(Eigen::Vector3d(1, 1.3, 0.5), 0.5));
  long seen = 0;
  try {
    integrate(*rk4, Eigen::Vector3d(0, 65, 500), 0.0, 10.0, 1000,
              [&](long k, double, const Eigen::Vector3d&) { seen = k + 1; });
    FAIL() << "no overflow";
  } catch (const NonFiniteState& e) {
    const std::string what = e.what();
    EXPECT_THAT(what, ::testing::HasSubstr("non-finite"));
    EXPECT_THAT(what, ::testing::HasSubstr("rk4 step " + std::to_string(e.step())));
    EXPECT_THAT(what, ::testing::Not(::testing::HasSubstr("residual")));
    EXPECT_EQ(e.step(), seen - 1);
    EXPECT_EQ(e.h(), 10.0);
  }
}

}  // namespace integrators_tests
}  // namespace ddb::test
