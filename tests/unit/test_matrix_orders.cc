// Fitted orders of every method of the table on the matrix groups (docs/reference/conventions.md
// §2): the Manakov body on SO(4) and the fluid on SU(8), α = 0.5 and α = 0, each final state at
// t = 1 against the adaptive reference; least-squares log–log slope over five to eight step sizes,
// the round-off plateau dropped (order_fit.h). The expected order is the table's own row:
// `order` with dissipation, `order_without_dissipation` without.
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "order_fit.h"
#include "test_support.h"

namespace ddb::test {
namespace matrix_orders_tests {

struct OrderCase {
  std::string system;  // "manakov" or "zeitlin"
  std::string method;
  double alpha;
};

/// Steps over t ∈ [0, 1]: errors between about 1e-3 and the round-off plateau for the order.
std::vector<int> stepCounts(int order) {
  if (order >= 6) return {4, 6, 8, 12, 16, 24, 32, 48};
  if (order >= 4) return {8, 16, 32, 64, 128};
  return {20, 40, 80, 160, 320};
}

template <class G>
double fittedSlope(std::shared_ptr<const LiePoissonSystem<G>> system,
                   const typename G::template Dual<double>& mu0, const MethodInfo& info,
                   double alpha, int& points) {
  using D = typename G::template Dual<double>;
  const auto finalState = [&](const MethodInfo& m, int steps) {
    auto method = makeMethod<G>(m, system);
    D last;
    integrate(*method, mu0, 0.0, 1.0 / steps, steps, [&](long, double, const D& mu) { last = mu; });
    return last;
  };
  const D reference = finalState(*findMethod("reference"), 1);
  std::vector<double> hs, errors;
  const int order = alpha == 0.0 ? info.order_without_dissipation : info.order;
  for (int steps : stepCounts(order)) {
    hs.push_back(1.0 / steps);
    errors.push_back((finalState(info, steps) - reference).norm() / reference.norm());
  }
  const OrderFit fit = fitOrder(hs, errors, 1e-12);
  points = fit.points;
  return fit.slope;
}

void PrintTo(const OrderCase& c, std::ostream* os) {
  *os << c.system << " " << c.method << " alpha " << c.alpha;
}

class MatrixOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(MatrixOrder, FittedSlopeIsTheTablesOrder) {
  const OrderCase& c = GetParam();
  const MethodInfo& info = *findMethod(c.method);
  const int expected = c.alpha == 0.0 ? info.order_without_dissipation : info.order;
  int points = 0;
  double slope = 0.0;
  if (c.system == "manakov") {
    Sampler sampler(7);
    const Eigen::Matrix4d a = sampler.vector<Eigen::Matrix4d>();
    const Eigen::MatrixXd M0 = a - a.transpose();
    slope = fittedSlope<SON>(makeManakovBody(Eigen::VectorXd::LinSpaced(4, 0.5, 2.0), c.alpha), M0,
                             info, c.alpha, points);
  } else {
    slope = fittedSlope<SUN>(makeZeitlinFluid(8, c.alpha), randomVorticity(8, 1), info, c.alpha,
                             points);
  }
  std::cout << c.system << " " << c.method << " alpha=" << c.alpha << " slope=" << slope
            << " points=" << points << "\n";
  ASSERT_GE(points, 4);
  EXPECT_NEAR(slope, expected, 0.2);
}

std::vector<OrderCase> everyMatrixMethod() {
  std::vector<OrderCase> cases;
  for (const char* system : {"manakov", "zeitlin"}) {
    for (const MethodInfo& m : kMethods) {
      if ((m.groups & kMatrixGroups) == 0 || m.order == 0) continue;
      for (double alpha : {0.5, 0.0}) cases.push_back({system, std::string(m.name), alpha});
    }
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, MatrixOrder, ::testing::ValuesIn(everyMatrixMethod()),
                         [](const auto& info) {
                           std::string name =
                               info.param.system + "_" + info.param.method +
                               (info.param.alpha == 0.0 ? "_conservative" : "_dissipative");
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace matrix_orders_tests
}  // namespace ddb::test
