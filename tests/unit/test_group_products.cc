// Groups made of groups (groups/semidirect_product.h, groups/direct_product.h). Two and three
// systems on direct products follow their own trajectories; SE(3) composed from SO(3)'s functions
// against SE3 written out, for every method of the table on the heavy top and Kirchhoff's body;
// SE(2)'s planar Kirchhoff body against its textbook equations, its double-bracket energy rate and
// Casimir by central differences, its relaxed state against the closed-form minimum of the energy
// on its orbit, and the fitted orders of the DDB family. Ratiu's heavy top on SE(N): at N = 3
// against SE3's in SpecialOrthogonal<3>'s coordinates for every method; at N = 4 its vector field
// against the Euler–Poisson equations in matrix form, its Casimirs, and its relaxed energy against
// the closed-form minimum on its orbit, and the fitted orders. Semidirect products by another
// representation: the ready-made ones and a user's own are representations, Ad on SO(3) gives SE(3)
// through the generic formulas, and a body on SO(3) ⋉ Sym(3) relaxes to the closed-form minimum
// on its orbit keeping tr Γ, tr Γ², tr Γ³, with the fitted orders. The products' retraction
// Jacobians against central differences (retraction_jacobian_suite.h). The groups' defining
// identities (Jacobi, the duals of ad and Ad, the Cayley map against the block matrices' Cayley
// map, exp against Eigen's matrix exponential) are the generic suites' (test_groups.cc,
// test_retractions.cc).
#include <ddb/groups/direct_product.h>
#include <ddb/groups/special_euclidean.h>
#include <ddb/integrators/drivers/integrate.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>
#include <ddb/systems/body_inertia.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/kirchhoff.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/planar_kirchhoff.h>
#include <ddb/systems/rigid_body.h>
#include <gmock/gmock.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <iostream>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "order_fit.h"
#include "retraction_jacobian_suite.h"
#include "test_support.h"

namespace ddb::test {
namespace group_products_tests {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using SE3Composed = SemidirectProduct<SO3>;

template <class G, class V>
std::vector<V> trajectory(const MethodInfo& info, std::shared_ptr<const LiePoissonSystem<G>> system,
                          const V& mu0, double h, long steps) {
  auto method = makeMethod<G>(info, system);
  std::vector<V> states;
  integrate(*method, mu0, 0.0, h, steps, [&](long, double, const V& mu) { states.push_back(mu); });
  return states;
}

TEST(SemidirectProduct, SE3ComposedFollowsSE3WrittenOutForEveryMethod) {
  const HeavyTopSetup top;
  const KirchhoffSetup body;
  struct Case {
    std::string name;
    std::shared_ptr<const LiePoissonSystem<SE3>> written;
    std::shared_ptr<const LiePoissonSystem<SE3Composed>> composed;
    Vector6 mu0;
  };
  std::vector<Case> cases;
  for (double alpha : {0.0, top.alpha}) {
    cases.push_back({"heavy top, alpha " + std::to_string(alpha),
                     makeHeavyTop(top.inertia, top.mgl, top.chi, alpha, top.metric),
                     makeHeavyTopOn<SE3Composed>(top.inertia, top.mgl, top.chi, alpha, top.metric),
                     top.mu0});
  }
  cases.push_back(
      {"kirchhoff", makeKirchhoffBody(body.inertia, body.mass, body.alpha, body.metric),
       makeKirchhoffBodyOn<SE3Composed>(body.inertia, body.mass, body.alpha, body.metric),
       body.mu0});
  int compared = 0;
  for (const Case& c : cases) {
    for (const MethodInfo& info : kMethods) {
      if (!methodApplies(info, *c.written)) continue;
      ASSERT_TRUE(methodApplies(info, *c.composed)) << info.name;
      const auto written = trajectory<SE3>(info, c.written, c.mu0, 0.05, 200);
      const auto composed = trajectory<SE3Composed>(info, c.composed, c.mu0, 0.05, 200);
      ASSERT_EQ(written.size(), composed.size());
      double worst = 0.0;
      for (size_t k = 0; k < written.size(); ++k) {
        worst = std::max(worst, (written[k] - composed[k]).norm());
      }
      EXPECT_LE(worst, 1e-13) << c.name << ", " << info.name;
      std::cout << c.name << ", " << info.name << ": largest difference " << worst << "\n";
      ++compared;
    }
  }
  EXPECT_GE(compared, 30);  // 11 on each heavy top (no Lagrangian, no scalar metric), 13 here
}

const double kInertia = 0.5;
const Eigen::Vector2d kMass(1.0, 3.0);
const Eigen::Vector3d kUnitMetric = Eigen::Vector3d::Ones();
const Eigen::Vector3d kMu0(0.3, 1.0, 0.2);

/// (P × v, ΩP₂, −ΩP₁): the planar Kirchhoff equations written out, v = P/m, Ω = π/I.
Eigen::Vector3d planarKirchhoffRate(const Eigen::Vector3d& mu) {
  const double omega = mu(0) / kInertia;
  const Eigen::Vector2d P = mu.tail<2>(), v = P.cwiseQuotient(kMass);
  return Eigen::Vector3d(P(0) * v(1) - P(1) * v(0), omega * P(1), -omega * P(0));
}

TEST(PlanarKirchhoff, VectorFieldIsThePlanarEquationsAndDissipatesAtTheDoubleBracketRate) {
  Sampler s(31);
  for (double alpha : {0.0, 0.4}) {
    const auto body = makePlanarKirchhoffBody(kInertia, kMass, alpha, kUnitMetric);
    for (int i = 0; i < 5; ++i) {
      const Eigen::Vector3d mu = s.vector<Eigen::Vector3d>();
      const Eigen::Vector3d f = body->vectorField(mu);
      const Eigen::Vector3d conservative = planarKirchhoffRate(mu);
      // (m₁ − m₂) v₁v₂, the Munk moment, for the first row.
      EXPECT_NEAR(conservative(0), (kMass(0) - kMass(1)) * mu(1) / kMass(0) * mu(2) / kMass(1),
                  1e-15);
      if (alpha == 0.0) {
        EXPECT_LT((f - conservative).norm(), 1e-15);
      }
      const double d = 1e-5;
      const Eigen::Vector3d plus = mu + d * f, minus = mu - d * f;
      EXPECT_NEAR((body->energy(plus) - body->energy(minus)) / (2 * d),
                  -alpha * conservative.squaredNorm(), 1e-8);
      EXPECT_LT(((body->casimirs(plus) - body->casimirs(minus)) / (2 * d)).norm(), 1e-8);
    }
  }
}

TEST(PlanarKirchhoff, AnalyticDerivativesMatchAutodiff) {
  const PlanarKirchhoffHamiltonian H(kInertia, kMass);
  const PlanarKirchhoffLagrangian l(kInertia, kMass);
  using HBase = AutoDiffHamiltonian<PlanarKirchhoffHamiltonian, SE2>;
  using LBase = AutoDiffLagrangian<PlanarKirchhoffLagrangian, SE2>;
  Sampler s(32);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d x = s.vector<Eigen::Vector3d>(), v = s.vector<Eigen::Vector3d>();
    EXPECT_LT((H.gradient(x) - H.HBase::gradient(x)).norm(), 1e-15);
    EXPECT_LT((H.hessianTimes(x, v) - H.HBase::hessianTimes(x, v)).norm(), 1e-15);
    EXPECT_LT((l.gradient(x) - l.LBase::gradient(x)).norm(), 1e-15);
    EXPECT_LT((l.hessianTimes(x, v) - l.LBase::hessianTimes(x, v)).norm(), 1e-15);
    // l and H are Legendre-dual: ∂H/∂μ at μ = ∂l/∂ξ is ξ.
    EXPECT_LT((H.gradient(l.gradient(x)) - x).norm(), 1e-15);
  }
}

/// A relaxation watched step by step: the largest rise of the energy from one state to the next,
/// the largest relative drift of any Casimir from μ₀'s, and the last state.
template <class V>
struct Watched {
  double rise = 0.0, casimir_drift = 0.0;
  V last;
};
template <class G>
Watched<typename G::template Dual<double>> watchRelaxation(
    OneStepMethod<G>& method, const LiePoissonSystem<G>& system,
    const typename G::template Dual<double>& mu0, double h, long steps) {
  using V = typename G::template Dual<double>;
  const Eigen::VectorXd c0 = system.casimirs(mu0);
  Watched<V> watched{0.0, 0.0, mu0};
  double previous = system.energy(mu0);
  integrate(method, mu0, 0.0, h, steps, [&](long, double, const V& mu) {
    const double e = system.energy(mu);
    watched.rise = std::max(watched.rise, e - previous);
    previous = e;
    watched.casimir_drift = std::max(
        watched.casimir_drift, (system.casimirs(mu) - c0).cwiseQuotient(c0).cwiseAbs().maxCoeff());
    watched.last = mu;
  });
  return watched;
}

TEST(PlanarKirchhoff, DdbRelaxesToTheEnergyMinimumOnItsOrbit) {
  // On |P| = c the energy ½π²/I + ½(P₁²/m₁ + P₂²/m₂) is least at π = 0, P along the axis of
  // the larger added mass: c²/(2 max m).
  const auto body = makePlanarKirchhoffBody(kInertia, kMass, 0.5, kUnitMetric);
  const double c2 = kMu0.tail<2>().squaredNorm();
  const double minimum = c2 / (2 * kMass.maxCoeff());
  for (const std::string name : {"ddb-cay", "ddb-exp-exact", "sddb-cay"}) {
    auto method = makeMethod<SE2>(name, body);
    const auto [rise, casimir_drift, last] = watchRelaxation<SE2>(*method, *body, kMu0, 0.05, 8000);
    EXPECT_LE(rise, 1e-15) << name;
    EXPECT_LE(casimir_drift, 1e-14) << name;
    EXPECT_NEAR(body->energy(last), minimum, 1e-12) << name;
    EXPECT_LT(std::abs(last(0)) + std::abs(last(1)), 1e-6) << name;
    std::cout << name << ": E - E_min " << body->energy(last) - minimum << ", Casimir drift "
              << casimir_drift << "\n";
  }
}

/// The fitted orders of ddb-cay, ddb-exp-exact, sddb-cay and ddb4-cay on the system that
/// `systemAt(α)` makes, at α = 0 and 0.5, from μ₀ to t_end against the reference method.
template <class G, class SystemAt>
void expectFittedOrdersOfTheDdbFamily(const std::string& label, const SystemAt& systemAt,
                                      const typename G::template Dual<double>& mu0, double t_end) {
  using V = typename G::template Dual<double>;
  const auto finalState = [&](OneStepMethod<G>& method, double h) {
    V last;
    integrate(method, mu0, 0.0, h, std::lround(t_end / h),
              [&](long, double, const V& mu) { last = mu; });
    return last;
  };
  for (double alpha : {0.0, 0.5}) {
    const std::shared_ptr<const LiePoissonSystem<G>> system = systemAt(alpha);
    ReferenceSolver<G> reference(system);
    const V exact = finalState(reference, 0.5);
    for (const std::string name : {"ddb-cay", "ddb-exp-exact", "sddb-cay", "ddb4-cay"}) {
      const MethodInfo& info = *findMethod(name);
      std::vector<double> hs{0.1, 0.05, 0.025, 0.0125}, errors;
      for (double h : hs) {
        auto method = makeMethod<G>(name, system);
        errors.push_back((finalState(*method, h) - exact).norm());
      }
      const OrderFit fit = fitOrder(hs, errors);
      ASSERT_GE(fit.points, 4) << label << " " << name;
      const int order = alpha == 0.0 ? info.order_without_dissipation : info.order;
      EXPECT_NEAR(fit.slope, order, 0.25) << label << " " << name << " alpha " << alpha;
      std::cout << label << " " << name << " alpha=" << alpha << " slope=" << fit.slope << "\n";
    }
  }
}

TEST(PlanarKirchhoff, FittedOrdersOfTheDdbFamily) {
  expectFittedOrdersOfTheDdbFamily<SE2>(
      "planar body",
      [](double alpha) { return makePlanarKirchhoffBody(kInertia, kMass, alpha, kUnitMetric); },
      kMu0, 5.0);
}

TEST(PlanarKirchhoff, RejectsBadParametersNamingThem) {
  using ::testing::HasSubstr;
  using ::testing::ThrowsMessage;
  EXPECT_THAT([] { makePlanarKirchhoffBody(-1.0, kMass, 0.5, kUnitMetric); },
              ThrowsMessage<InvalidArgument>(HasSubstr("inertia")));
  EXPECT_THAT([] { makePlanarKirchhoffBody(kInertia, Eigen::Vector2d(1, 0), 0.5, kUnitMetric); },
              ThrowsMessage<InvalidArgument>(HasSubstr("mass")));
  EXPECT_THAT([] { makePlanarKirchhoffBody(kInertia, Eigen::Vector2d(1, NAN), 0.5, kUnitMetric); },
              ThrowsMessage<InvalidArgument>(HasSubstr("mass")));
  EXPECT_THAT([] { makePlanarKirchhoffBody(kInertia, kMass, 0.5, -kUnitMetric); },
              ThrowsMessage<InvalidArgument>(HasSubstr("metric")));
  EXPECT_THAT([] { makePlanarKirchhoffBody(kInertia, kMass, INFINITY, kUnitMetric); },
              ThrowsMessage<InvalidArgument>(HasSubstr("alpha")));
}

// Systems side by side on a direct product P = First × Second: H = H₁ + H₂ and k♯ = α I, each
// block delegated to its system's own Hamiltonian, so that the product's flow is both flows at
// once.
template <class P>
class SideBySideHamiltonian final : public Hamiltonian<P> {
 public:
  using A = typename P::First;
  using B = typename P::Second;
  using V = typename P::template Dual<double>;
  SideBySideHamiltonian(std::shared_ptr<const LiePoissonSystem<A>> a,
                        std::shared_ptr<const LiePoissonSystem<B>> b)
      : a_(std::move(a)), b_(std::move(b)) {}
  double value(const V& mu) const override {
    return a_->energy(P::first(mu)) + b_->energy(P::second(mu));
  }
  V gradient(const V& mu) const override {
    return P::template join<double>(a_->hamiltonian().gradient(P::first(mu)),
                                    b_->hamiltonian().gradient(P::second(mu)));
  }
  V hessianTimes(const V& mu, const V& v) const override {
    return P::template join<double>(a_->hamiltonian().hessianTimes(P::first(mu), P::first(v)),
                                    b_->hamiltonian().hessianTimes(P::second(mu), P::second(v)));
  }

 private:
  std::shared_ptr<const LiePoissonSystem<A>> a_;
  std::shared_ptr<const LiePoissonSystem<B>> b_;
};

template <class P>
std::shared_ptr<const LiePoissonSystem<P>> sideBySide(
    std::shared_ptr<const LiePoissonSystem<typename P::First>> a,
    std::shared_ptr<const LiePoissonSystem<typename P::Second>> b, double alpha) {
  return makeLiePoissonSystem(
      "side-by-side", std::make_shared<const SideBySideHamiltonian<P>>(std::move(a), std::move(b)),
      std::make_shared<const ScaledIdentityMetric<P>>(alpha));
}

// The rigid body of Scenario A and the planar body side by side on SO(3) × SE(2).
using SO3xSE2 = DirectProduct<SO3, SE2>;
using Vector6Product = SO3xSE2::Dual<double>;

TEST(DirectProduct, TwoSystemsSideBySideFollowTheirOwnTrajectories) {
  const RigidBodyScenario& scenario = rigidBodyScenario("A");
  const double alpha = scenario.alpha;
  const auto body = makeRigidBody(scenario.inertia, alpha);
  const auto planar = makePlanarKirchhoffBody(kInertia, kMass, alpha, kUnitMetric);
  const auto both = sideBySide<SO3xSE2>(body, planar, alpha);
  const Vector6Product mu0 = SO3xSE2::join<double>(scenario.mu0(), kMu0);
  int compared = 0;
  for (const MethodInfo& info : kMethods) {
    // Not the implicit rows (the planar body's metric is diagonal) nor sddb-paper-* (no l here).
    if (!methodApplies(info, *both) || !methodApplies(info, *planar)) continue;
    const auto product = trajectory<SO3xSE2>(info, both, mu0, 0.05, 200);
    const auto first = trajectory<SO3>(info, body, scenario.mu0(), 0.05, 200);
    const auto second = trajectory<SE2>(info, planar, kMu0, 0.05, 200);
    ASSERT_EQ(product.size(), first.size());
    double worst = 0.0;
    for (size_t k = 0; k < product.size(); ++k) {
      worst = std::max(worst, (SO3xSE2::join<double>(first[k], second[k]) - product[k]).norm());
    }
    // The implicit methods solve for both blocks at once, to the tolerance of the joint residual,
    // where the separate runs stop each block's solve at its own: solve errors of 1e-15 per step.
    EXPECT_LE(worst, info.kind == MethodKind::kExplicitRk4 ? 0.0 : 1e-13) << info.name;
    std::cout << "side by side, " << info.name << ": largest difference " << worst << "\n";
    ++compared;
  }
  EXPECT_EQ(compared, 11);
}

TEST(DirectProduct, ThreeSystemsSideBySideFollowTheirOwnTrajectories) {
  // SO(3) × SE(2) × SO(3), the product of three factors, is SO(3) × (SE(2) × SO(3)): the rigid
  // bodies of Scenarios A and C and the planar body between them.
  using Triple = DirectProduct<SO3, SE2, SO3>;
  using Pair = Triple::Second;
  static_assert(std::is_same_v<Pair, DirectProduct<SE2, SO3>>);
  const double alpha = rigidBodyScenario("A").alpha;
  const RigidBodyScenario& a = rigidBodyScenario("A");
  const RigidBodyScenario& c = rigidBodyScenario("C");
  const auto bodyA = makeRigidBody(a.inertia, alpha);
  const auto bodyC = makeRigidBody(c.inertia, alpha);
  const auto planar = makePlanarKirchhoffBody(kInertia, kMass, alpha, kUnitMetric);
  const auto all = sideBySide<Triple>(bodyA, sideBySide<Pair>(planar, bodyC, alpha), alpha);
  EXPECT_STREQ(Triple::kName, "SO3xSE2xSO3");
  const Triple::Dual<double> mu0 = Triple::join<double>(a.mu0(), Pair::join<double>(kMu0, c.mu0()));
  int compared = 0;
  for (const MethodInfo& info : kMethods) {
    if (!methodApplies(info, *all) || !methodApplies(info, *planar)) continue;
    const auto product = trajectory<Triple>(info, all, mu0, 0.05, 200);
    const auto first = trajectory<SO3>(info, bodyA, a.mu0(), 0.05, 200);
    const auto second = trajectory<SE2>(info, planar, kMu0, 0.05, 200);
    const auto third = trajectory<SO3>(info, bodyC, c.mu0(), 0.05, 200);
    ASSERT_EQ(product.size(), first.size());
    double worst = 0.0;
    for (size_t k = 0; k < product.size(); ++k) {
      const Triple::Dual<double> separate =
          Triple::join<double>(first[k], Pair::join<double>(second[k], third[k]));
      worst = std::max(worst, (separate - product[k]).norm());
    }
    // As for two systems: the implicit solves stop on the joint residual.
    EXPECT_LE(worst, info.kind == MethodKind::kExplicitRk4 ? 0.0 : 1e-13) << info.name;
    std::cout << "three side by side, " << info.name << ": largest difference " << worst << "\n";
    ++compared;
  }
  EXPECT_EQ(compared, 11);
}

// ---- Ratiu's heavy top on SE(N) (groups/special_euclidean.h, systems/heavy_top.h) ----

using SE3Fixed = SpecialEuclidean<3>;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
using SE4 = SpecialEuclidean<4>;
using Vector10 = Eigen::Matrix<double, 10, 1>;

/// SO3's coordinates of so(3) from SpecialOrthogonal<3>'s (x₀₁, x₀₂, x₁₂): (x₁₂, −x₀₂, x₀₁). The
/// map is its own inverse.
Eigen::Vector3d so3Coordinates(const Eigen::Vector3d& p) { return {p(2), -p(1), p(0)}; }
Vector6 se3Coordinates(const Vector6& mu) {
  return (Vector6() << so3Coordinates(mu.head<3>()), mu.tail<3>()).finished();
}

TEST(SpecialEuclidean, HeavyTopInThreeDimensionsIsSE3sForEveryMethod) {
  const HeavyTopSetup top;
  // The same top in SpecialOrthogonal<3>'s coordinates: the principal moments and the metric's
  // rotational weights in the order of the pairs (the signs drop out of a diagonal).
  const Eigen::Vector3d inertia = so3Coordinates(top.inertia).cwiseAbs();
  const Vector6 metric = se3Coordinates(top.metric).cwiseAbs();
  const Vector6 mu0 = se3Coordinates(top.mu0);
  int compared = 0;
  for (double alpha : {0.0, top.alpha}) {
    const auto written = makeHeavyTop(top.inertia, top.mgl, top.chi, alpha, top.metric);
    const auto fixed = makeHeavyTopOn<SE3Fixed>(inertia, top.mgl, top.chi, alpha, metric);
    for (const MethodInfo& info : kMethods) {
      if (!methodApplies(info, *written)) continue;
      ASSERT_TRUE(methodApplies(info, *fixed)) << info.name;
      const auto a = trajectory<SE3>(info, written, top.mu0, 0.05, 200);
      const auto b = trajectory<SE3Fixed>(info, fixed, mu0, 0.05, 200);
      ASSERT_EQ(a.size(), b.size());
      double worst = 0.0;
      for (size_t k = 0; k < a.size(); ++k) {
        worst = std::max(worst, (se3Coordinates(a[k]) - b[k]).norm());
      }
      // SpecialOrthogonal<3> runs LieGroupBase's matrix formulas where SO3 has cross products: a
      // rounding apart per step, which α = 0 does not damp. Bound: 4 ulp of |μ| per step.
      EXPECT_LE(worst, 200 * 4 * kEpsilon * mu0.norm()) << "alpha " << alpha << ", " << info.name;
      std::cout << "SE(3) fixed, alpha " << alpha << ", " << info.name << ": largest difference "
                << worst << "\n";
      ++compared;
    }
  }
  EXPECT_EQ(compared, 22);
}

// A four-dimensional top: mass moments J, so that the largest principal moment J₀ + J₁ is one of
// the block {0, 1, 2} orthogonal to χ = e₃ (the closed-form minimum below needs it).
const Eigen::Vector4d kMassMoments(2.0, 1.5, 1.0, 0.5);
const Eigen::Vector4d kChi(0.0, 0.0, 0.0, 1.0);
const double kMgl = 0.8;

Vector10 topState() {
  Vector10 mu;
  mu << 0.4, -0.3, 0.2, 0.5, -0.1, 0.3, 0.6, -0.4, 0.2, 0.7;
  return mu;
}

TEST(SpecialEuclidean, HeavyTopVectorFieldIsTheEulerPoissonEquations) {
  // Ratiu's equations in matrix form, M = hat(π), Ω = hat(𝕀⁻¹π):
  //   Ṁ = [M, Ω] + mgℓ(χγᵀ − γχᵀ),  γ̇ = −Ωγ
  // (at N = 3, π̇ = π × Ω + mgℓ γ × χ and γ̇ = γ × Ω), and E decreases at the double bracket's rate
  // −α‖ad*_{∂H/∂μ} μ‖² for the unit metric.
  using SO4 = SpecialOrthogonal<4>;
  const Eigen::Matrix<double, 6, 1> inertia = bodyInertiaOf<4>(kMassMoments);
  Sampler s(41);
  for (double alpha : {0.0, 0.3}) {
    const auto top = makeHeavyTopOn<SE4>(inertia, kMgl, kChi, alpha, Vector10::Ones());
    for (int i = 0; i < 5; ++i) {
      const Vector10 mu = s.vector<Vector10>();
      const Eigen::Matrix4d M = SO4::hat<double>(mu.head<6>());
      const Eigen::Matrix4d Omega = SO4::hat<double>(mu.head<6>().cwiseQuotient(inertia).eval());
      const Eigen::Vector4d gamma = mu.tail<4>();
      const Eigen::Matrix4d Mdot =
          M * Omega - Omega * M + kMgl * (kChi * gamma.transpose() - gamma * kChi.transpose());
      Vector10 conservative;
      conservative << SO4::vee<double>(Mdot), -Omega * gamma;
      const Vector10 f = top->vectorField(mu);
      if (alpha == 0.0) {
        EXPECT_LT((f - conservative).norm(), 1e-14);
      }
      const double d = 1e-5;
      const Vector10 plus = mu + d * f, minus = mu - d * f;
      EXPECT_NEAR((top->energy(plus) - top->energy(minus)) / (2 * d),
                  -alpha * conservative.squaredNorm(), 1e-8);
      const Eigen::VectorXd rate = (top->casimirs(plus) - top->casimirs(minus)) / (2 * d);
      EXPECT_LT(rate.norm(), 1e-8);
    }
  }
}

TEST(SpecialEuclidean, HeavyTopRelaxesToTheEnergyMinimumOnItsOrbit) {
  // On the orbit of |γ| = r and c₁ = r⁴‖P M P‖²_F = 2r⁴s² (s² the squared norm of π's block
  // orthogonal to γ), E ≥ s²/(2 max 𝕀) − mgℓ r|χ|: the kinetic part is at least ½|π|²/max 𝕀 and
  // |π|² ≥ s²; the bound is reached at γ = −rχ/|χ| with π all on the largest moment of the block
  // orthogonal to χ. (The top's orbit has this point since max 𝕀 = J₀ + J₁ is in that block.)
  // The last mode to settle, π's exchange between the pairs (0, 1) and (0, 3), decays by about e
  // in t = 100: E is at its minimum to 1e-10 from t ≈ 1500 on.
  const Eigen::Matrix<double, 6, 1> inertia = bodyInertiaOf<4>(kMassMoments);
  const auto top = makeHeavyTopOn<SE4>(inertia, kMgl, kChi, 0.5, Vector10::Ones());
  const Vector10 mu0 = topState();
  const Eigen::VectorXd c0 = top->casimirs(mu0);
  const double r = std::sqrt(c0(0));
  const double s2 = c0(1) / (2 * std::pow(r, 4));
  const double minimum = s2 / (2 * inertia.maxCoeff()) - kMgl * r * kChi.norm();
  for (const std::string name : {"ddb-cay", "ddb-exp-exact", "sddb-cay"}) {
    auto method = makeMethod<SE4>(name, top);
    const auto [rise, casimir_drift, last] = watchRelaxation<SE4>(*method, *top, mu0, 0.05, 32000);
    EXPECT_LE(rise, 1e-15) << name;
    // c₁ is of degree 6 in μ: one rounding of the state per step moves it by at most about 6 ulp,
    // and over 32000 steps such roundings may add up.
    EXPECT_LE(casimir_drift, 6 * 32000 * kEpsilon) << name;
    EXPECT_NEAR(top->energy(last), minimum, 1e-10) << name;
    std::cout << "SE(4) heavy top, " << name << ": E - E_min " << top->energy(last) - minimum
              << ", Casimir drift " << casimir_drift << "\n";
  }
}

TEST(SpecialEuclidean, FittedOrdersOfTheDdbFamilyOnTheHeavyTop) {
  const Eigen::Matrix<double, 6, 1> inertia = bodyInertiaOf<4>(kMassMoments);
  expectFittedOrdersOfTheDdbFamily<SE4>(
      "SE(4) heavy top",
      [&](double alpha) {
        return makeHeavyTopOn<SE4>(inertia, kMgl, kChi, alpha, Vector10::Ones());
      },
      topState(), 2.0);
}

TEST(SpecialEuclidean, HeavyTopRejectsBadParametersNamingThem) {
  using ::testing::HasSubstr;
  using ::testing::ThrowsMessage;
  const Eigen::Matrix<double, 6, 1> inertia = bodyInertiaOf<4>(kMassMoments);
  EXPECT_THAT([] { bodyInertiaOf<4>(Eigen::Vector4d(1.0, 0.0, 1.0, 1.0)); },
              ThrowsMessage<InvalidArgument>(HasSubstr("mass_moments")));
  EXPECT_THAT([&] { makeHeavyTopOn<SE4>(-inertia, kMgl, kChi, 0.5, Vector10::Ones()); },
              ThrowsMessage<InvalidArgument>(HasSubstr("inertia")));
  EXPECT_THAT(
      [&] {
        makeHeavyTopOn<SE4>(inertia, kMgl, Eigen::Vector4d(0, NAN, 0, 1), 0.5, Vector10::Ones());
      },
      ThrowsMessage<InvalidArgument>(HasSubstr("chi")));
  EXPECT_THAT([&] { makeHeavyTopOn<SE4>(inertia, NAN, kChi, 0.5, Vector10::Ones()); },
              ThrowsMessage<InvalidArgument>(HasSubstr("mgl")));
  EXPECT_THAT([&] { makeHeavyTopOn<SE4>(inertia, kMgl, kChi, 0.5, -Vector10::Ones()); },
              ThrowsMessage<InvalidArgument>(HasSubstr("metric")));
}

// ---- Semidirect products by another representation (groups/representation.h) ----

// The ready-made representations and the user's own (symmetric_matrices_representation.h) are
// representations: ρ(gh) = ρ(g)ρ(h), and ρ'(ω) is the derivative of ρ(exp tω) at t = 0 (by
// central differences).
template <class G, class Rep>
void expectRepresentation(const std::string& label) {
  using A = typename G::template Algebra<double>;
  Sampler s(7);
  for (int i = 0; i < 5; ++i) {
    const A x = s.vector<A>(), y = s.vector<A>();
    const auto g = G::exp(x), h = G::exp(y);
    const auto product = Rep::template ofGroup<double>(G::compose(g, h));
    EXPECT_LT(
        (product - Rep::template ofGroup<double>(g) * Rep::template ofGroup<double>(h)).norm(),
        1e-13)
        << label;
    const double d = 1e-5;
    const auto rate = ((Rep::template ofGroup<double>(G::exp(A(d * x))) -
                        Rep::template ofGroup<double>(G::exp(A(-d * x)))) /
                       (2 * d))
                          .eval();
    EXPECT_LT((rate - Rep::template ofAlgebra<double>(x)).norm(), 1e-9) << label;
  }
}

TEST(SemidirectProduct, RepresentationsAreRepresentations) {
  using SO4 = SpecialOrthogonal<4>;
  expectRepresentation<SO4, DefiningRepresentation<SO4>>("SO(4) on R^4");
  expectRepresentation<SO4, AdjointRepresentation<SO4>>("SO(4) on so(4)");
  expectRepresentation<SO4, CoadjointRepresentation<SO4>>("SO(4) on so(4)*");
  expectRepresentation<SO3, SymmetricMatrices>("SO(3) on Sym(3)");
  // SO(N)'s coordinates are orthonormal for an invariant inner product, so Ad_g is orthogonal
  // and the coadjoint action Ad*_{g^-1} is the adjoint one.
  Sampler s(8);
  for (int i = 0; i < 3; ++i) {
    const auto g = SO4::exp(s.vector<SO4::Algebra<double>>());
    EXPECT_LT((AdjointRepresentation<SO4>::ofGroup<double>(g) -
               CoadjointRepresentation<SO4>::ofGroup<double>(g))
                  .norm(),
              1e-14);
  }
}

}  // namespace group_products_tests
}  // namespace ddb::test

namespace ddb {
/// SO(3) acting on so(3) by Ad: Ad_R = R in SO3's coordinates, so it is SE(3) again.
template <>
struct SemidirectProductTraits<SO3, AdjointRepresentation<SO3>> {
  static constexpr const char* kName = "SO3 x|Ad so3";
  static constexpr int kNumCasimirs = 2;
  template <class T>
  static Eigen::Matrix<T, 2, 1> casimirs(const Eigen::Matrix<T, 3, 1>& pi,
                                         const Eigen::Matrix<T, 3, 1>& gamma) {
    return Eigen::Matrix<T, 2, 1>(gamma.squaredNorm(), pi.dot(gamma));
  }
};
}  // namespace ddb

namespace ddb::test {
namespace group_products_tests {

TEST(SemidirectProduct, AdjointActionOfSO3IsSE3ThroughTheGenericFormulas) {
  // The product by a representation other than G's own matrices takes the generic path (the
  // (p+m+1)-square elements, A = 2(I + ρ(cay ω))⁻¹ by a solve, the diamond through G's pairing),
  // which for Ad on SO(3) must give the functions of SE(3) composed by G's own matrices. Those
  // take SO(3)'s vector forms of the action and the diamond (groups/se3.h), which ByAd's traits
  // do not give: the two sides share no formula for them.
  using ByAd = SemidirectProduct<SO3, AdjointRepresentation<SO3>>;
  static_assert(!ByAd::kOwnMatrices && ByAd::kMatrixDim == 7);
  static_assert(SE3Composed::kVectorForms && !ByAd::kVectorForms);
  Sampler s(9);
  for (int i = 0; i < 5; ++i) {
    const Vector6 x = s.vector<Vector6>(), y = s.vector<Vector6>(), mu = s.vector<Vector6>();
    EXPECT_LT((ByAd::bracket(x, y) - SE3Composed::bracket(x, y)).norm(), 1e-15);
    EXPECT_LT((ByAd::adDual(x, mu) - SE3Composed::adDual(x, mu)).norm(), 1e-15);
    EXPECT_LT((ByAd::dcay(x, y) - SE3Composed::dcay(x, y)).norm(), 1e-14);
    EXPECT_LT((ByAd::dcayInv(x, y) - SE3Composed::dcayInv(x, y)).norm(), 1e-14);
    EXPECT_LT((ByAd::dcayInvDual(x, mu) - SE3Composed::dcayInvDual(x, mu)).norm(), 1e-14);
    EXPECT_LT((ByAd::cayAdDual(x, mu) - SE3Composed::cayAdDual(x, mu)).norm(), 1e-14);
    EXPECT_LT((ByAd::cayInverse(ByAd::cay(x)) - x).norm(), 1e-14);
    EXPECT_LT(
        (ByAd::AdDual(ByAd::exp(x), mu) - SE3Composed::AdDual(SE3Composed::exp(x), mu)).norm(),
        1e-14);
    EXPECT_LT((ByAd::log(ByAd::exp(x)) - x).norm(), 1e-14);
    EXPECT_LT((ByAd::dcayInvDualMatrix(x) - SE3Composed::dcayInvDualMatrix(x)).norm(), 1e-14);
  }
}

/// The spectral radius of a square matrix, from its eigenvalues (on the dynamic-size matrix: one
/// eigensolver compiled for every size).
double spectralRadius(const Eigen::MatrixXd& a) {
  return Eigen::EigenSolver<Eigen::MatrixXd>(a, false).eigenvalues().cwiseAbs().maxCoeff();
}

/// The spectral radius of ad_x from the matrix whose columns are [x, e_j]: block triangular on a
/// semidirect product (checked), so the larger of its diagonal blocks' (the whole matrix's
/// eigenvalues are defective, each twice on SE(3), and an eigensolver finds those to √ε only).
template <class G>
double spectralRadiusOfAd(const typename G::template Algebra<double>& x) {
  using Algebra = typename G::template Algebra<double>;
  constexpr int n = G::kDim, p = G::kFactorDim, m = G::kVectorDim;
  Eigen::MatrixXd ad(n, n);
  for (int j = 0; j < n; ++j) {
    ad.col(j) = G::bracket(x, Algebra(Algebra::Unit(j)));
  }
  EXPECT_EQ(ad.topRightCorner(p, m).norm(), 0.0);
  return std::max(spectralRadius(ad.topLeftCorner(p, p)),
                  spectralRadius(ad.bottomRightCorner(m, m)));
}

// The injectivity guard's adRadius is the spectral radius of ad_x where the traits give Ω's
// (SO(3)'s |ω|: SE(3) composed) and at least it otherwise (the product by Ad on SO(3), SE(4)).
TEST(SemidirectProduct, AdRadiusIsTheSpectralRadiusOfAdOrAnUpperBound) {
  using ByAd = SemidirectProduct<SO3, AdjointRepresentation<SO3>>;
  Sampler s(47);
  for (int i = 0; i < 20; ++i) {
    const Vector6 x = s.vector<Vector6>();
    const double radius = spectralRadiusOfAd<SE3Composed>(x);
    EXPECT_NEAR(SE3Composed::adRadius(x), radius, 1e-14 * radius);
    EXPECT_NEAR(SE3::adRadius(x), radius, 1e-14 * radius);
    const Eigen::Vector3d w = x.head<3>();  // Ω = ω̂ on SE(3)
    const double algebra_action_radius = spectralRadius(SO3::hat(w));
    EXPECT_NEAR(SemidirectProductTraits<SO3>::algebraActionRadius(w), algebra_action_radius,
                1e-14 * algebra_action_radius);
    EXPECT_GE(ByAd::adRadius(x), radius * (1 - 1e-14));
    const SE4::Algebra<double> y = s.vector<SE4::Algebra<double>>();
    EXPECT_GE(SE4::adRadius(y), spectralRadiusOfAd<SE4>(y) * (1 - 1e-14));
  }
}

// A body in a field whose potential is linear in its orientation tensor (a gravity-gradient
// torque) on SO(3) ⋉ Sym(3): H = ½ πᵀ𝕀⁻¹π + mgℓ χ·γ, the heavy top's Hamiltonian on this group
// (systems/heavy_top.h takes any semidirect product).
using SO3xSym = SemidirectProduct<SO3, SymmetricMatrices>;
using Vector9 = Eigen::Matrix<double, 9, 1>;
const Eigen::Vector3d kBodyInertia(1.0, 2.0, 3.0);
const double kField = 0.7;

Eigen::Matrix<double, 6, 1> fieldTensor() {
  return SymmetricMatrices::coordinatesOf<double>(
      (Eigen::Matrix3d() << 1.0, 0.3, 0.0, 0.3, -0.5, 0.2, 0.0, 0.2, 0.1).finished());
}

Vector9 orientedBodyState() {
  Vector9 mu;
  mu.head<3>() << 0.4, -0.6, 0.5;
  mu.tail<6>() = SymmetricMatrices::coordinatesOf<double>(
      (Eigen::Matrix3d() << 0.8, 0.1, -0.2, 0.1, 0.3, 0.4, -0.2, 0.4, -0.6).finished());
  return mu;
}

std::shared_ptr<const LiePoissonSystem<SO3xSym>> orientedBody(double alpha) {
  return makeHeavyTopOn<SO3xSym>(kBodyInertia, kField, fieldTensor(), alpha, Vector9::Ones());
}

TEST(SemidirectProduct, UserRepresentationRelaxesToTheEnergyMinimumOnItsOrbit) {
  // On the orbit, Γ = matrixOf(γ) keeps its spectrum λ and π is free (Γ's stabiliser is discrete),
  // so E ≥ mgℓ min_R tr(X R Γ₀ Rᵀ) = mgℓ Σ x↑_i λ↓_i (X = matrixOf(χ); von Neumann's trace
  // inequality, reached where Γ is diagonal in X's eigenbasis in opposite order) with π = 0.
  const auto body = orientedBody(0.5);
  const Vector9 mu0 = orientedBodyState();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> field(
      SymmetricMatrices::matrixOf<double>(fieldTensor()));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> orientation(
      SymmetricMatrices::matrixOf<double>(Eigen::Matrix<double, 6, 1>(mu0.tail<6>())));
  const double minimum = kField * field.eigenvalues().dot(orientation.eigenvalues().reverse());
  int ran = 0;
  for (const MethodInfo& info : kMethods) {
    if (!methodApplies(info, *body) || !info.keeps_casimirs) continue;
    ++ran;
    auto method = makeMethod<SO3xSym>(info, body);
    const auto [rise, casimir_drift, last] =
        watchRelaxation<SO3xSym>(*method, *body, mu0, 0.1, 6000);
    EXPECT_LE(rise, 1e-15) << info.name;
    // tr Γ³ is of degree 3 in γ: a rounding of the state per step moves it by a few ulp.
    EXPECT_LE(casimir_drift, 3 * 6000 * kEpsilon) << info.name;
    EXPECT_NEAR(body->energy(last), minimum, 1e-10) << info.name;
    std::cout << "SO(3) x Sym(3), " << info.name << ": E - E_min " << body->energy(last) - minimum
              << ", Casimir drift " << casimir_drift << "\n";
  }
  // The DDB rows with a diagonal metric and no Lagrangian: ddb-cay, ddb-exp, ddb-exp-exact,
  // sddb-cay, sddb-exp, ddb4-cay, ddb4-exp, ddb6-exp.
  EXPECT_EQ(ran, 8);
}

TEST(SemidirectProduct, FittedOrdersOfTheDdbFamilyOnAUserRepresentation) {
  expectFittedOrdersOfTheDdbFamily<SO3xSym>("SO(3) x Sym(3)", orientedBody, orientedBodyState(),
                                            2.0);
}

// The Cayley retraction of a product by another ρ, (cay_G ω, A⁻¹v) with A⁻¹ = (I + ρ(cay_G ω))/2,
// is singular where ρ(cay_G ω) has the eigenvalue −1: on Sym(3), ρ(R) turns by 2θ for R's angle
// θ = 2 atan(|ω|/2), so at |ω| = 2. Unlike exp past π, it is one-to-one on both sides (cay_G is,
// and A⁻¹ is invertible off that set), so a step past it has no other branch to land on: the
// Legendre solve either solves the same equations (the Casimirs kept) or fails by name near the
// pole (docs/reference/guarantees.md §2). Never a NaN.
TEST(SemidirectProduct, CayleyStepsPastTheSingularSetOfAUserRepresentationSolveOrFailByName) {
  const auto body =
      makeHeavyTopOn<SO3xSym>(kBodyInertia, 0.01, fieldTensor(), 0.5, Vector9::Ones());
  const Vector9 mu0 = orientedBodyState();
  const Eigen::VectorXd c0 = body->casimirs(mu0);
  int solved_past = 0, failed = 0;
  for (const std::string name : {"ddb-cay", "sddb-cay"}) {
    for (double h = 2.0; h <= 6.0; h += 0.25) {
      auto method = makeMethod<SO3xSym>(name, body);
      Vector9 mu = mu0;
      try {
        for (int k = 0; k < 20; ++k) {
          const double turn = h * body->velocity(mu).head<3>().norm();
          mu = method->step(mu, k * h, h);
          ASSERT_TRUE(mu.allFinite()) << name << " h " << h;
          EXPECT_LT((body->casimirs(mu) - c0).cwiseQuotient(c0).cwiseAbs().maxCoeff(), 1e-13)
              << name << " h " << h;
          if (turn > 2.0) ++solved_past;
        }
      } catch (const SolveFailure& e) {
        EXPECT_THAT(e.what(), ::testing::HasSubstr("did not converge")) << name << " h " << h;
        ++failed;
      }
    }
  }
  EXPECT_GT(solved_past, 0);  // the runs cross |hω| = 2 (at h = 4.75: |hω| up to 2.9)
  EXPECT_GT(failed, 0);
}

// The retraction Jacobian suite (retraction_jacobian_suite.h) on the products' retractions, in
// this unit, which instantiates their Newton solves' Jacobians for the method tables already.
using ProductRetractions =
    ::testing::Types<Cayley<SE3Composed>, Exponential<SE3Composed>, Cayley<DirectProduct<SO3, SE2>>,
                     Exponential<DirectProduct<SO3, SE2>>, Cayley<SpecialEuclidean<4>>,
                     Exponential<SpecialEuclidean<4>>,
                     Cayley<SemidirectProduct<SO3, SymmetricMatrices>>,
                     Exponential<SemidirectProduct<SO3, SymmetricMatrices>>>;
INSTANTIATE_TYPED_TEST_SUITE_P(RetractionJacobianTest, RetractionJacobianTest, ProductRetractions);

}  // namespace group_products_tests
}  // namespace ddb::test
