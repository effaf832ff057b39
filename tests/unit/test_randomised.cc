// Randomised checks (docs/reference/guarantees.md §3): seeded random valid parameter sets per
// system — inertia over four decades, α of both signs over five decades, h over three,
// random momenta and a random DDB method. Every run either keeps the Casimirs to 1e-13
// relative with finite states, or stops with a typed ddb error (SolveFailure and its
// subclasses); never a NaN, an abort or an untyped exception. The outcome counts are
// printed (and recorded as test properties) so that their distribution can be reported.
#include <ddb/core/errors.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/kirchhoff.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ddb::test {
namespace randomised_tests {

constexpr double kCasimirTolerance = 1e-13;
constexpr long kSteps = 10;

class Draw {
 public:
  explicit Draw(std::uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng_); }
  double logUniform(double lo_exp, double hi_exp) {
    return std::pow(10.0, uniform(lo_exp, hi_exp));
  }
  double signedLog(double lo_exp, double hi_exp) {
    return (uniform(-1, 1) < 0 ? -1.0 : 1.0) * logUniform(lo_exp, hi_exp);
  }
  template <class V>
  V vector(Eigen::Index n = V::RowsAtCompileTime) {
    V v(n);
    for (Eigen::Index i = 0; i < n; ++i) v(i) = uniform(-1, 1);
    return v;
  }
  const std::string& pick(const std::vector<std::string>& names) {
    return names[std::uniform_int_distribution<std::size_t>(0, names.size() - 1)(rng_)];
  }
  std::uint64_t seed() { return rng_(); }

 private:
  std::mt19937_64 rng_;
};

/// At least this share of the runs must complete: every system completes 64% to 83% of its
/// sets (docs/reference/guarantees.md §3), so a regression to "every run throws a SolveFailure",
/// which each run alone would accept, fails the suite.
constexpr double kMinimumCompletedShare = 0.5;

/// Outcome counts by kind; prints and records them at the end of a suite, and checks the
/// share of completed runs.
struct Outcomes {
  std::map<std::string, int> counts;
  double worst_drift = 0.0;
  void report(const std::string& system) const {
    int total = 0;
    for (const auto& entry : counts) total += entry.second;
    const auto completed = counts.find("completed");
    const int done = completed == counts.end() ? 0 : completed->second;
    EXPECT_GE(done, kMinimumCompletedShare * total) << system << ": " << done << " of " << total;
    std::ostringstream os;
    os << system << ":";
    for (const auto& [kind, n] : counts) os << " " << kind << " " << n << ";";
    os << " worst Casimir drift of completed runs " << worst_drift;
    std::cout << os.str() << "\n";
    for (const auto& [kind, n] : counts) ::testing::Test::RecordProperty(system + "." + kind, n);
  }
};

/// One run of `steps` steps: the outcome's kind. Checks every state it sees: finite,
/// Casimir drift (relative, by `drift`) at most kCasimirTolerance. An exception that is
/// not a SolveFailure propagates and fails the test.
template <class G>
std::string runOne(OneStepMethod<G>& method, const typename G::template Dual<double>& mu0, double h,
                   const std::function<double(const typename G::template Dual<double>&)>& drift,
                   const std::string& label, Outcomes& outcomes) {
  using Dual = typename G::template Dual<double>;
  double worst = 0.0;
  const auto check = [&](long, double, const Dual& mu) {
    EXPECT_TRUE(mu.allFinite()) << label;
    worst = std::max(worst, drift(mu));
  };
  std::string kind = "completed";
  try {
    integrate(method, mu0, 0.0, h, kSteps, check);
  } catch (const InjectivityLimit&) {
    kind = "InjectivityLimit";
  } catch (const BudgetExhausted&) {
    kind = "BudgetExhausted";
  } catch (const NonFiniteState&) {
    kind = "NonFiniteState";
  } catch (const SolveFailure&) {
    kind = "SolveFailure";
  }
  EXPECT_LE(worst, kCasimirTolerance) << label << " (" << kind << ")";
  if (kind == "completed") outcomes.worst_drift = std::max(outcomes.worst_drift, worst);
  ++outcomes.counts[kind];
  return kind;
}

/// The DDB methods of the table that run on `families` and need no Lagrangian (nor, unless
/// `include_scalar_metric_methods`, the metric α·I), in table order.
std::vector<std::string> ddbMethods(unsigned families, bool include_scalar_metric_methods = true) {
  std::vector<std::string> names;
  for (const MethodInfo& m : kMethods) {
    if ((m.groups & families) != 0 && m.keeps_casimirs && !m.needs_lagrangian &&
        (include_scalar_metric_methods || !m.needs_scalar_metric)) {
      names.emplace_back(m.name);
    }
  }
  return names;
}
const std::vector<std::string> kSmallMethods = ddbMethods(kFixedSizeGroups);
/// The heavy top's and Kirchhoff body's metric is α·diag(k).
const std::vector<std::string> kSe3Methods = ddbMethods(kFixedSizeGroups, false);

std::string describe(const std::string& method, double alpha, double h, int i) {
  std::ostringstream os;
  os.precision(17);
  os << "set " << i << ": " << method << ", alpha " << alpha << ", h " << h;
  return os.str();
}

TEST(Randomised, RigidBody) {
  Draw draw(20261121);
  Outcomes outcomes;
  std::vector<std::string> methods = kSmallMethods;
  methods.insert(methods.end(), {"sddb-paper-cay", "sddb-paper-exp"});
  for (int i = 0; i < 1000; ++i) {
    Eigen::Vector3d inertia;
    for (int j = 0; j < 3; ++j) inertia(j) = draw.logUniform(-2, 2);
    const double alpha = draw.signedLog(-3, 2);
    const double h = draw.logUniform(-3, 0);
    const Eigen::Vector3d mu0 = draw.vector<Eigen::Vector3d>() * draw.logUniform(-1, 1);
    const std::string& name = draw.pick(methods);
    auto system = makeRigidBody(inertia, alpha);
    auto method = makeMethod<SO3>(name, system);
    const double c0 = mu0.norm();
    runOne<SO3>(
        *method, mu0, h, [&](const Eigen::Vector3d& mu) { return std::abs(mu.norm() - c0) / c0; },
        describe(name, alpha, h, i), outcomes);
  }
  outcomes.report("rigid-body");
}

// SE(3) Casimirs |γ|² and π·γ. The coadjoint orbits are not compact: π grows without
// bound on them (energy ascent, or a falling top turning potential into kinetic energy),
// and π·γ can only be evaluated to round-off of |π||γ| in the current state. So π·γ is
// measured relative to the largest |π||γ| the run has seen (its initial value at least),
// |γ|² relative to itself.
class Se3Drift {
 public:
  explicit Se3Drift(const Vector6d& mu0)
      : mu0_(mu0), scale_(mu0.head<3>().norm() * mu0.tail<3>().norm()) {}
  double operator()(const Vector6d& mu) {
    scale_ = std::max(scale_, mu.head<3>().norm() * mu.tail<3>().norm());
    const double g0 = mu0_.tail<3>().squaredNorm();
    return std::max(
        std::abs(mu.tail<3>().squaredNorm() - g0) / g0,
        std::abs(mu.head<3>().dot(mu.tail<3>()) - mu0_.head<3>().dot(mu0_.tail<3>())) / scale_);
  }

 private:
  Vector6d mu0_;
  double scale_;
};

template <class Make>
void runSe3(const std::string& system_name, std::uint64_t seed, const Make& make) {
  Draw draw(seed);
  Outcomes outcomes;
  for (int i = 0; i < 1000; ++i) {
    const double alpha = draw.signedLog(-3, 2);
    const double h = draw.logUniform(-3, 0);
    Vector6d metric;
    for (int j = 0; j < 6; ++j) metric(j) = draw.uniform(0, 1);
    const Vector6d mu0 = draw.vector<Vector6d>() * draw.logUniform(-1, 1);
    const std::string& name = draw.pick(kSe3Methods);
    auto system = make(draw, alpha, metric);
    auto method = makeMethod<SE3>(name, system);
    runOne<SE3>(*method, mu0, h, Se3Drift(mu0), describe(name, alpha, h, i), outcomes);
  }
  outcomes.report(system_name);
}

TEST(Randomised, HeavyTop) {
  runSe3("heavy-top", 11, [](Draw& draw, double alpha, const Vector6d& metric) {
    Eigen::Vector3d inertia;
    for (int j = 0; j < 3; ++j) inertia(j) = draw.logUniform(-2, 2);
    const Eigen::Vector3d chi = draw.vector<Eigen::Vector3d>();
    return makeHeavyTop(inertia, draw.signedLog(-2, 2), chi, alpha, metric);
  });
}

TEST(Randomised, Kirchhoff) {
  runSe3("kirchhoff", 12, [](Draw& draw, double alpha, const Vector6d& metric) {
    Eigen::Vector3d inertia, mass;
    for (int j = 0; j < 3; ++j) inertia(j) = draw.logUniform(-2, 2);
    for (int j = 0; j < 3; ++j) mass(j) = draw.logUniform(-2, 2);
    return makeKirchhoffBody(inertia, mass, alpha, metric);
  });
}

// Matrix groups: Casimirs are the spectrum of −iμ, relative to its largest magnitude.
template <class G>
double spectrumDrift(const Eigen::VectorXd& spectrum0,
                     const typename G::template Dual<double>& mu) {
  return (G::casimirs(mu) - spectrum0).cwiseAbs().maxCoeff() / spectrum0.cwiseAbs().maxCoeff();
}

const std::vector<std::string> kMatrixMethods = ddbMethods(kMatrixGroups);

/// 1000 sets at N = 3, 4, 5; make(draw, n, alpha) returns the system and μ₀.
template <class G, class Make>
void runMatrixGroup(const std::string& system_name, std::uint64_t seed, const Make& make) {
  using Dual = typename G::template Dual<double>;
  Draw draw(seed);
  Outcomes outcomes;
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Index n = 3 + i % 3;
    const double alpha = draw.signedLog(-3, 2);
    const double h = draw.logUniform(-3, 0);
    const auto [system, mu0] = make(draw, n, alpha);
    const std::string& name = draw.pick(kMatrixMethods);
    auto method = makeMethod<G>(name, system);
    const Eigen::VectorXd spectrum0 = G::casimirs(mu0);
    runOne<G>(
        *method, mu0, h, [&](const Dual& mu) { return spectrumDrift<G>(spectrum0, mu); },
        describe(name, alpha, h, i) + ", N " + std::to_string(n), outcomes);
  }
  outcomes.report(system_name);
}

TEST(Randomised, ManakovBody) {
  runMatrixGroup<SON>("manakov-body", 13, [](Draw& draw, Eigen::Index n, double alpha) {
    Eigen::VectorXd J(n);
    for (Eigen::Index j = 0; j < n; ++j) J(j) = draw.logUniform(-2, 2);
    const Eigen::MatrixXd a = draw.vector<Eigen::VectorXd>(n * n).reshaped(n, n);
    return std::make_pair(makeManakovBody(J, alpha),
                          Eigen::MatrixXd((a - a.transpose()) * draw.logUniform(-1, 1)));
  });
}

TEST(Randomised, ZeitlinFluid) {
  runMatrixGroup<SUN>("zeitlin-fluid", 14, [](Draw& draw, Eigen::Index n, double alpha) {
    return std::make_pair(
        makeZeitlinFluid(n, alpha),
        Eigen::MatrixXcd(randomVorticity(n, draw.seed()) * draw.logUniform(-1, 1)));
  });
}

}  // namespace randomised_tests
}  // namespace ddb::test
