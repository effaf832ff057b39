// The small Legendre solver's initial guess, PolynomialPredictor: it continues polynomials of
// degree below its order exactly, climbs one order per step while higher orders predict
// better, keeps to low orders on noise, and restarts from the three corrections of the 0.2.0
// record as the quadratic extrapolation that record was written for. The references are closed
// forms: the polynomials' next values, the backward differences of an exponential,
// 3c − 3c′ + c″.
#include <ddb/integrators/solvers/polynomial_predictor.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>

namespace ddb::test {
namespace polynomial_predictor_tests {

constexpr int kOrder = 8;
using Predictor = PolynomialPredictor<Eigen::Vector3d, kOrder>;
const Eigen::Vector3d kNear(0.3, -1.2, 0.7);

// Σ_j a_j s^j at s = k/10 (scaled so that the powers stay O(1) over the steps used).
Eigen::Vector3d polynomial(const std::array<Eigen::Vector3d, kOrder>& a, int degree, int k) {
  const double s = 0.1 * k;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  for (int j = degree; j >= 0; --j) value = value * s + a[static_cast<std::size_t>(j)];
  return value;
}

TEST(PolynomialPredictor, ContinuesEveryPolynomialOfDegreeBelowItsOrder) {
  std::array<Eigen::Vector3d, kOrder> a;
  for (int j = 0; j < kOrder; ++j) {
    a[static_cast<std::size_t>(j)] = Eigen::Vector3d(std::sin(j + 1.0), std::cos(2.0 * j), 0.5 - j);
  }
  for (int degree = 0; degree < kOrder; ++degree) {
    Predictor predictor;
    for (int k = 0; k < kOrder + 2; ++k) predictor.remember(polynomial(a, degree, k));
    // Orders above the degree miss by rounding only; the one chosen is among them.
    EXPECT_GT(predictor.order(), degree) << "degree " << degree;
    for (int k = kOrder + 2; k < kOrder + 8; ++k) {
      const Eigen::Vector3d expected = kNear + polynomial(a, degree, k);
      EXPECT_LT((predictor.predict(kNear) - expected).norm(), 1e-11 * expected.norm())
          << "degree " << degree << ", step " << k;
      predictor.remember(expected - kNear);
    }
  }
}

TEST(PolynomialPredictor, ClimbsOneOrderPerStepWhileTheHighestPredictsBest) {
  // c_k = e^{λk} v: its m-th backward difference, the miss of order m, is (1 − e^{−λ})^m c_k,
  // smaller at every higher order, so the order climbs by one per step to the most.
  const double lambda = 0.1;
  const Eigen::Vector3d v(1.0, 2.0, -0.5);
  Predictor predictor;
  EXPECT_EQ(predictor.order(), 0);
  EXPECT_EQ(predictor.predict(kNear), kNear);
  for (int k = 0; k < kOrder + 4; ++k) {
    predictor.remember(std::exp(lambda * k) * v);
    EXPECT_EQ(predictor.order(), std::min(k + 1, kOrder)) << "after " << k + 1;
  }
  // At the full order the miss is the 8th difference, (1 − e^{−λ})⁸ c_next.
  const int next = kOrder + 4;
  const Eigen::Vector3d expected = std::exp(lambda * next) * v;
  const double miss = (predictor.predict(kNear) - kNear - expected).norm();
  EXPECT_NEAR(miss, std::pow(1.0 - std::exp(-lambda), kOrder) * expected.norm(), 1e-4 * miss);
}

TEST(PolynomialPredictor, KeepsToLowOrdersOnNoise) {
  // Corrections a constant plus independent noise of deviation σ per entry: order 1 misses
  // by about √2 σ per entry and order m by √C(2m, m) σ, 80 times more at m = 8. The predictor's
  // guesses must miss, on average, within three times order 1's, far from the high orders'.
  std::mt19937_64 random(7);
  const auto noise = [&] {  // uniform on [−√3, √3] σ: deviation σ, the same on every platform
    Eigen::Vector3d e;
    for (int i = 0; i < 3; ++i)
      e(i) = (static_cast<double>(random() >> 11) * 0x1p-53 - 0.5) * 2 * std::sqrt(3.0);
    return e;
  };
  const double sigma = 1e-3;
  const Eigen::Vector3d constant(0.2, 0.1, -0.3);
  Predictor predictor;
  double squared_misses = 0.0, orders = 0.0;
  const int steps = 400;
  for (int k = 0; k < steps; ++k) {
    const Eigen::Vector3d c = constant + sigma * noise();
    if (k >= kOrder) {
      squared_misses += (predictor.predict(kNear) - kNear - c).squaredNorm();
      orders += predictor.order();
    }
    predictor.remember(c);
  }
  const double samples = steps - kOrder;
  EXPECT_LT(orders / samples, 2.5);
  // Order 1's expected squared miss is 2σ² per entry, 6σ² in all; order 2's 18σ².
  EXPECT_LT(squared_misses / samples, 3.0 * 6.0 * sigma * sigma);
}

TEST(PolynomialPredictor, RestartsFromThreeCorrectionsAsTheirQuadraticExtrapolation) {
  const std::array<Eigen::Vector3d, 3> newest_first = {Eigen::Vector3d(0.11, -0.2, 0.05),
                                                       Eigen::Vector3d(0.1, -0.21, 0.04),
                                                       Eigen::Vector3d(0.08, -0.23, 0.035)};
  const auto& [c0, c1, c2] = newest_first;
  const std::array<Eigen::Vector3d, 4> expected = {kNear, kNear + c0, kNear + 2 * c0 - c1,
                                                   kNear + 3 * c0 - 3 * c1 + c2};
  for (int count = 0; count <= 3; ++count) {
    Predictor predictor;
    predictor.restart(newest_first, count);
    EXPECT_EQ(predictor.order(), count);
    EXPECT_LT((predictor.predict(kNear) - expected[static_cast<std::size_t>(count)]).norm(), 1e-15)
        << count << " corrections";
  }
}

TEST(PolynomialPredictor, ARecordRestoresTheSamePredictions) {
  Predictor predictor;
  for (int k = 0; k < 11; ++k)
    predictor.remember(Eigen::Vector3d(std::sin(0.3 * k), k, 1.0 / (k + 1)));
  BinaryRecordWriter out;
  predictor.save(out);
  Predictor restored;
  BinaryRecordReader in(out.bytes());
  restored.load(in);
  EXPECT_EQ(restored.order(), predictor.order());
  EXPECT_EQ(restored.predict(kNear), predictor.predict(kNear));  // to the bit
  // A count beyond the table is refused, not read.
  BinaryRecordWriter bad;
  bad.tag("polynomial predictor");
  bad.put(kOrder + 1);
  bad.put(1);
  BinaryRecordReader bad_in(bad.bytes());
  EXPECT_THROW(restored.load(bad_in), CorruptRecord);
  for (const auto& [count, order] : {std::pair{-1, 0}, std::pair{3, 4}}) {
    BinaryRecordWriter counts;
    counts.tag("polynomial predictor");
    counts.put(count);
    counts.put(order);
    BinaryRecordReader counts_in(counts.bytes());
    EXPECT_THROW(restored.load(counts_in), CorruptRecord) << count << ", " << order;
  }
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  EXPECT_THROW(restored.restart(std::array<Eigen::Vector3d, 3>{zero, zero, zero}, 4),
               InvalidArgument);
}

}  // namespace polynomial_predictor_tests
}  // namespace ddb::test
