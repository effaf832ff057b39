// The heavy top and the Kirchhoff body on se(3)*: vector fields against the
// textbook equations, the double-bracket energy rate and Casimirs by central
// differences, and DDB (Hamiltonian form for the heavy top) against the reference.
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/kirchhoff.h>
#include <ddb/systems/paper_scenarios.h>
#include <gmock/gmock.h>

#include "order_fit.h"
#include "test_support.h"

namespace ddb::test {
namespace se3_systems_tests {

using Vector6 = Eigen::Matrix<double, 6, 1>;
const HeavyTopSetup kTop;
const KirchhoffSetup kKirchhoff;
const Eigen::Vector3d kInertia = kTop.inertia;
const Eigen::Vector3d kMass = kKirchhoff.mass;
const Eigen::Vector3d kChi = kTop.chi;
const double kMgl = kTop.mgl;
const Vector6 kUnitMetric = kTop.metric;
const Vector6 kTopMu0 = kTop.mu0;

TEST(HeavyTop, VectorFieldIsTheHeavyTopAndDissipatesAtTheDoubleBracketRate) {
  Sampler s(21);
  for (double alpha : {0.0, 0.4}) {
    const auto top = makeHeavyTop(kInertia, kMgl, kChi, alpha, kUnitMetric);
    for (int i = 0; i < 5; ++i) {
      const Vector6 mu = s.vector<Vector6>();
      const Eigen::Vector3d pi = mu.head<3>(), gamma = mu.tail<3>();
      const Eigen::Vector3d omega = pi.cwiseQuotient(kInertia);
      const Vector6 f = top->vectorField(mu);
      if (alpha == 0.0) {
        EXPECT_LT((f.head<3>() - (pi.cross(omega) + kMgl * gamma.cross(kChi))).norm(), 1e-14);
        EXPECT_LT((f.tail<3>() - gamma.cross(omega)).norm(), 1e-14);
      }
      const double d = 1e-5;
      const Vector6 plus = mu + d * f, minus = mu - d * f;
      // ad*_ξ μ with ξ = (Ω, mgl χ), written out: (π×Ω + γ×mgl χ, γ×Ω).
      Vector6 adStar;
      adStar << pi.cross(omega) + gamma.cross(kMgl * kChi), gamma.cross(omega);
      EXPECT_NEAR((top->energy(plus) - top->energy(minus)) / (2 * d), -alpha * adStar.squaredNorm(),
                  1e-8);
      EXPECT_LT(((top->casimirs(plus) - top->casimirs(minus)) / (2 * d)).norm(), 1e-8);
    }
  }
}

TEST(Kirchhoff, VectorFieldIsKirchhoffsEquations) {
  const auto body = makeKirchhoffBody(kInertia, kMass, 0.0, kUnitMetric);
  Sampler s(22);
  for (int i = 0; i < 5; ++i) {
    const Vector6 mu = s.vector<Vector6>();
    const Eigen::Vector3d pi = mu.head<3>(), P = mu.tail<3>();
    const Eigen::Vector3d omega = pi.cwiseQuotient(kInertia), v = P.cwiseQuotient(kMass);
    const Vector6 f = body->vectorField(mu);
    EXPECT_LT((f.head<3>() - (pi.cross(omega) + P.cross(v))).norm(), 1e-14);
    EXPECT_LT((f.tail<3>() - P.cross(omega)).norm(), 1e-14);
    EXPECT_LT((body->lagrangian()->gradient(body->velocity(mu)) - mu).norm(), 1e-14);
  }
}

Vector6 finalState(OneStepMethod<SE3>& method, const Vector6& mu0, double h, double t_end) {
  Vector6 last;
  integrate(method, mu0, 0.0, h, std::lround(t_end / h),
            [&](long, double, const Vector6& mu) { last = mu; });
  return last;
}

TEST(HeavyTop, HamiltonianDdbOrdersAndCasimirs) {
  for (double alpha : {0.0, 0.5}) {
    const auto top = makeHeavyTop(kInertia, kMgl, kChi, alpha, kUnitMetric);
    ReferenceSolver<SE3> reference(top);
    const Vector6 exact = finalState(reference, kTopMu0, 0.5, 5.0);
    for (const std::string name : {"ddb-cay", "ddb-exp-exact"}) {
      std::vector<double> hs{0.05, 0.025, 0.0125, 0.00625}, errors;
      for (double h : hs) {
        auto method = makeMethod<SE3>(name, top);
        errors.push_back((finalState(*method, kTopMu0, h, 5.0) - exact).norm());
      }
      const OrderFit fit = fitOrder(hs, errors);
      ASSERT_GE(fit.points, 4);
      EXPECT_NEAR(fit.slope, alpha == 0.0 ? 2.0 : 1.0, 0.25) << name << " alpha " << alpha;
      std::cout << "heavy top " << name << " alpha=" << alpha << " slope=" << fit.slope << "\n";
    }
    auto ddb = makeMethod<SE3>("ddb-cay", top);
    const auto c0 = top->casimirs(kTopMu0);
    double drift = 0.0;
    integrate(*ddb, kTopMu0, 0.0, 0.1, 10000, [&](long, double, const Vector6& mu) {
      drift = std::max(drift, (top->casimirs(mu) - c0).cwiseQuotient(c0).cwiseAbs().maxCoeff());
    });
    EXPECT_LE(drift, 1e-13);
    std::cout << "heavy top ddb-cay alpha=" << alpha << " Casimir drift " << drift << "\n";
  }
}

TEST(HeavyTop, LagrangianFormIsRejectedWithAReason) {
  const auto top = makeHeavyTop(kInertia, kMgl, kChi, 0.5, kUnitMetric);
  EXPECT_THAT([&] { Ddb<Cayley<SE3>> ddb(top, Cayley<SE3>(), LegendreForm::kLagrangian); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("no Lagrangian")));
}

TEST(Kirchhoff, LagrangianAndHamiltonianDdbAgree) {
  const auto body = makeKirchhoffBody(kInertia, kMass, 0.5, kUnitMetric);
  const Vector6 mu0 = kKirchhoff.mu0;
  Ddb<Cayley<SE3>> lagrangian(body, Cayley<SE3>(), LegendreForm::kLagrangian);
  Ddb<Cayley<SE3>> hamiltonian(body, Cayley<SE3>(), LegendreForm::kHamiltonian);
  EXPECT_LT(
      (finalState(lagrangian, mu0, 0.1, 20.0) - finalState(hamiltonian, mu0, 0.1, 20.0)).norm(),
      1e-12);
}

TEST(SE3Systems, AnalyticDerivativesMatchAutodiff) {
  const HeavyTopHamiltonian top(kInertia, kMgl, Eigen::Vector3d(0.3, -0.2, 0.9));
  const KirchhoffHamiltonian H(kInertia, kMass);
  const KirchhoffLagrangian l(kInertia, kMass);
  using TopBase = AutoDiffHamiltonian<HeavyTopHamiltonian, SE3>;
  using HBase = AutoDiffHamiltonian<KirchhoffHamiltonian, SE3>;
  using LBase = AutoDiffLagrangian<KirchhoffLagrangian, SE3>;
  Sampler s(23);
  for (int i = 0; i < 5; ++i) {
    const Vector6 x = s.vector<Vector6>(), v = s.vector<Vector6>();
    EXPECT_LT((top.gradient(x) - top.TopBase::gradient(x)).norm(), 1e-15);
    EXPECT_LT((top.hessianTimes(x, v) - top.TopBase::hessianTimes(x, v)).norm(), 1e-15);
    EXPECT_LT((H.gradient(x) - H.HBase::gradient(x)).norm(), 1e-15);
    EXPECT_LT((H.hessianTimes(x, v) - H.HBase::hessianTimes(x, v)).norm(), 1e-15);
    EXPECT_LT((l.gradient(x) - l.LBase::gradient(x)).norm(), 1e-15);
    EXPECT_LT((l.hessianTimes(x, v) - l.LBase::hessianTimes(x, v)).norm(), 1e-15);
    Eigen::Matrix<double, 6, 6> top_columns, H_columns, l_columns;  // column by column by Jets
    for (int j = 0; j < 6; ++j) {
      top_columns.col(j) = top.TopBase::hessianTimes(x, Vector6::Unit(j));
      H_columns.col(j) = H.HBase::hessianTimes(x, Vector6::Unit(j));
      l_columns.col(j) = l.LBase::hessianTimes(x, Vector6::Unit(j));
    }
    EXPECT_LT((top.hessian(x) - top_columns).norm(), 1e-15);
    EXPECT_LT((H.hessian(x) - H_columns).norm(), 1e-15);
    EXPECT_LT((l.hessian(x) - l_columns).norm(), 1e-15);
  }
}

TEST(SE3Systems, RejectBadParametersNamingThem) {
  EXPECT_THAT([] { makeHeavyTop(kInertia, NAN, kChi, 0.5, kUnitMetric); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("mgl")));
  EXPECT_THAT([] { makeHeavyTop(kInertia, 1.0, kChi, 0.5, -kUnitMetric); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("metric")));
  EXPECT_THAT([] { makeKirchhoffBody(kInertia, Eigen::Vector3d(1, 0, 1), 0.5, kUnitMetric); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("mass")));
}

}  // namespace se3_systems_tests
}  // namespace ddb::test
