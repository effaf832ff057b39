// Symmetric DDB variants and their compositions on the rigid body of Scenario A:
// orders fitted against the reference (docs/reference/conventions.md §2 facts), symmetry Φ_{-h}∘Φ_h
// = id, and exact Casimir preservation by every stage.
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>
#include <gmock/gmock.h>

#include "order_fit.h"
#include "test_support.h"

namespace ddb::test {
namespace symmetric_tests {

const Eigen::Vector3d kInertia = rigidBodyScenario("A").inertia;
const Eigen::Vector3d kM0 = rigidBodyScenario("A").mu0();

Eigen::Vector3d finalState(OneStepMethod<SO3>& method, double h, double t_end) {
  Eigen::Vector3d last;
  integrate(method, kM0, 0.0, h, std::lround(t_end / h),
            [&](long, double, const Eigen::Vector3d& mu) { last = mu; });
  return last;
}

using Factory = std::function<std::unique_ptr<OneStepMethod<SO3>>(
    std::shared_ptr<const LiePoissonSystem<SO3>>)>;

struct OrderCase {
  std::string label;
  Factory make;
  double t_end;
  std::vector<double> hs;
  double expected;
};

Factory fromTable(const std::string& name) {
  return [name](auto system) { return makeMethod<SO3>(name, system); };
}
/// The order the method table claims for `name` with α ≠ 0 (these cases use α = 0.5).
double tableOrder(const std::string& name) { return findMethod(name)->order; }
template <class R>
Factory paperVariant(typename PaperSymmetricDdb<R>::Force force,
                     typename PaperSymmetricDdb<R>::ReadOut read_out) {
  return [=](auto system) {
    return std::make_unique<PaperSymmetricDdb<R>>(system, R(), force, read_out);
  };
}
using PaperCay = PaperSymmetricDdb<Cayley<SO3>>;
using PaperExp = PaperSymmetricDdb<Exponential<SO3>>;

class SymmetricOrderTest : public ::testing::TestWithParam<OrderCase> {};

TEST_P(SymmetricOrderTest, FittedSlope) {
  const OrderCase& c = GetParam();
  auto body = makeRigidBody(kInertia, 0.5);
  ReferenceSolver<SO3> reference(body);
  const Eigen::Vector3d exact = finalState(reference, c.t_end / 1000, c.t_end);
  std::vector<double> errors;
  for (double h : c.hs) {
    auto method = c.make(body);
    errors.push_back((finalState(*method, h, c.t_end) - exact).norm());
  }
  for (double h : c.hs) ASSERT_NEAR(std::lround(c.t_end / h) * h, c.t_end, 1e-12);
  const OrderFit fit = fitOrder(c.hs, errors, 1e-12);
  ASSERT_GE(fit.points, 4) << c.label;
  EXPECT_NEAR(fit.slope, c.expected, 0.3) << c.label;
  std::cout << c.label << ": slope " << fit.slope << " over " << fit.points << " step sizes\n";
}

// The paper's variant in its asymptotic regime (h <= 0.01, t in [0, 2]); at larger h the
// Cayley variant shows a transient second-order term.
const std::vector<double> kPaperSteps{0.01, 0.005, 0.0025, 0.00125};
const std::vector<double> kSecondOrderSteps{0.1, 0.05, 0.025, 0.0125};
const std::vector<double> kFourthOrderSteps{0.2, 0.1, 0.05, 0.025};
const std::vector<double> kSixthOrderSteps{0.5, 0.4, 0.25, 0.2, 0.125};  // divide t_end

INSTANTIATE_TEST_SUITE_P(
    ScenarioA, SymmetricOrderTest,
    ::testing::Values(OrderCase{"sddb_paper_cay", fromTable("sddb-paper-cay"), 2.0, kPaperSteps,
                                tableOrder("sddb-paper-cay")},
                      OrderCase{"sddb_paper_exp", fromTable("sddb-paper-exp"), 2.0, kPaperSteps,
                                tableOrder("sddb-paper-exp")},
                      OrderCase{"sddb_paper_cay_trapezoidal",
                                paperVariant<Cayley<SO3>>(PaperCay::Force::kTrapezoidal,
                                                          PaperCay::ReadOut::kAsWritten),
                                2.0, kPaperSteps, 1.0},
                      OrderCase{"sddb_paper_cay_halfforce",
                                paperVariant<Cayley<SO3>>(PaperCay::Force::kMidpoint,
                                                          PaperCay::ReadOut::kHalfForce),
                                10.0, kSecondOrderSteps, 2.0},
                      OrderCase{"sddb_paper_exp_halfforce",
                                paperVariant<Exponential<SO3>>(PaperExp::Force::kMidpoint,
                                                               PaperExp::ReadOut::kHalfForce),
                                10.0, kSecondOrderSteps, 2.0},
                      OrderCase{"sddb_cay", fromTable("sddb-cay"), 10.0, kSecondOrderSteps,
                                tableOrder("sddb-cay")},
                      OrderCase{"sddb_exp", fromTable("sddb-exp"), 10.0, kSecondOrderSteps,
                                tableOrder("sddb-exp")},
                      OrderCase{"sddb_cay_hamiltonian",
                                [](auto system) {
                                  return std::make_unique<SymmetricDdb<Cayley<SO3>>>(
                                      system, Cayley<SO3>(), LegendreForm::kHamiltonian);
                                },
                                10.0, kSecondOrderSteps, 2.0},
                      OrderCase{"ddb4_cay", fromTable("ddb4-cay"), 10.0, kFourthOrderSteps,
                                tableOrder("ddb4-cay")},
                      OrderCase{"ddb4_exp", fromTable("ddb4-exp"), 10.0, kFourthOrderSteps,
                                tableOrder("ddb4-exp")},
                      OrderCase{"ddb6_exp", fromTable("ddb6-exp"), 10.0, kSixthOrderSteps,
                                tableOrder("ddb6-exp")}),
    [](const auto& info) { return info.param.label; });

TEST(SymmetricDdb, StepBackwardsUndoesStepForwards) {
  auto body = makeRigidBody(kInertia, 0.5);
  Sampler s(31);
  for (const std::string name : {"sddb-cay", "sddb-exp"}) {
    for (LegendreForm form : {LegendreForm::kLagrangian, LegendreForm::kHamiltonian}) {
      std::unique_ptr<OneStepMethod<SO3>> method;
      if (name == "sddb-cay")
        method = std::make_unique<SymmetricDdb<Cayley<SO3>>>(body, Cayley<SO3>(), form);
      else
        method = std::make_unique<SymmetricDdb<Exponential<SO3>>>(body, Exponential<SO3>(), form);
      for (int i = 0; i < 5; ++i) {
        const Eigen::Vector3d mu = s.vector<Eigen::Vector3d>();
        for (double h : {0.1, 0.3}) {
          method->reset();
          const Eigen::Vector3d forward = method->step(mu, 0.0, h);
          const Eigen::Vector3d back = method->step(forward, h, -h);
          EXPECT_LT((back - mu).norm(), 1e-13) << name << " h " << h;
        }
      }
    }
  }
  // DDB itself is not symmetric: the same test shows an O(h²) defect.
  Ddb<Cayley<SO3>> ddb(body);
  const Eigen::Vector3d forward = ddb.step(kM0, 0.0, 0.1);
  EXPECT_GT((ddb.step(forward, 0.1, -0.1) - kM0).norm(), 1e-5);
}

TEST(SymmetricDdb, EveryMethodKeepsTheCasimirOverTenThousandSteps) {
  auto body = makeRigidBody(kInertia, 0.5);
  for (const MethodInfo& info : kMethods) {  // every symmetric or composed DDB on SO(3)
    if (!info.keeps_casimirs || info.kind == MethodKind::kDdb) continue;
    const std::string name(info.name);
    auto method = makeMethod<SO3>(name, body);
    double drift = 0.0;
    integrate(*method, kM0, 0.0, 0.1, 10000, [&](long, double, const Eigen::Vector3d& mu) {
      drift = std::max(drift, std::abs(mu.norm() - kM0.norm()) / kM0.norm());
    });
    EXPECT_LE(drift, 1e-13) << name;
    std::cout << name << ": max relative Casimir drift " << drift << "\n";
  }
}

TEST(PaperSymmetricDdb, RestartsWhenTheCallerChangesTheState) {
  // The two-step recurrence must not carry ξ_k into an unrelated trajectory.
  auto body = makeRigidBody(kInertia, 0.5);
  auto a = makeMethod<SO3>("sddb-paper-cay", body);
  auto b = makeMethod<SO3>("sddb-paper-cay", body);
  const Eigen::Vector3d other(0.3, -0.2, 0.1);
  a->step(kM0, 0.0, 0.1);
  EXPECT_LT((a->step(other, 0.0, 0.1) - b->step(other, 0.0, 0.1)).norm(), 1e-15);
}

TEST(PaperSymmetricDdb, NeedsALagrangian) {
  auto top = std::make_shared<const LiePoissonSystem<SO3>>(
      "hamiltonian-only", std::make_shared<const RigidBodyHamiltonian>(kInertia),
      std::make_shared<const ScaledIdentityMetric<SO3>>(0.5));
  EXPECT_FALSE(methodApplies("sddb-paper-cay", *top));
  EXPECT_TRUE(methodApplies("sddb-cay", *top));
  EXPECT_THAT([&] { makeMethod<SO3>("sddb-paper-cay", top); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("Lagrangian")));
}

}  // namespace symmetric_tests
}  // namespace ddb::test
