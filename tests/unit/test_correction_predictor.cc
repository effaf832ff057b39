// The Legendre solver's initial guess, CorrectionPredictor: linear prediction continues exactly
// what obeys a linear recurrence, and a prediction out of scale is not trusted.

#include <ddb/integrators/solvers/correction_predictor.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace ddb::test {
namespace correction_predictor_tests {

using Matrix = Eigen::MatrixXcd;

// Any sequence obeying a linear recurrence of order <= 6 (polynomials of degree <= 5 in k,
// geometric sequences and their sums) is continued exactly by the linear prediction; the
// closed form of the next term is the reference.
TEST(CorrectionPredictor, ContinuesSequencesThatObeyALinearRecurrence) {
  const int n = 9;
  const Matrix A = randomVorticity(n, 31), B = randomVorticity(n, 32), C = randomVorticity(n, 33);
  const Matrix near = randomVorticity(n, 34);
  const std::vector<std::function<Matrix(int)>> sequences = {
      [&](int k) { return Matrix(A + k * B + 0.5 * k * k * C); },  // degree 2
      [&](int k) { return Matrix(1e-3 * std::pow(k, 5) * A + std::pow(k, 3) * B - C); },
      [&](int k) { return Matrix(A + std::pow(0.5, k) * B + std::pow(-0.3, k) * C); },
      [&](int k) { return Matrix(std::pow(0.9, k) * A + k * std::pow(0.9, k) * B + C); },
  };
  for (std::size_t i = 0; i < sequences.size(); ++i) {
    CorrectionPredictor<Matrix> predictor;
    Matrix guess(n, n);
    const int warm = CorrectionPredictor<Matrix>::kOrder + 3;  // the full order from here on
    for (int k = 0; k < warm; ++k) predictor.remember(near + sequences[i](k), near);
    EXPECT_EQ(predictor.order(), CorrectionPredictor<Matrix>::kOrder);
    for (int k = warm; k < warm + 5; ++k) {
      predictor.predict(near, guess);
      const Matrix expected = near + sequences[i](k);
      EXPECT_LT((guess - expected).norm(), 1e-9 * expected.norm())
          << "sequence " << i << " k " << k;
      predictor.remember(expected, near);
    }
  }
}

// A predicted correction more than twice the largest remembered one is not trusted (a
// state off the remembered trajectory, a caller that skipped reset()): the guess is then
// the newest correction. Corrections tripling at each step predict a tripled one.
TEST(CorrectionPredictor, APredictionBeyondTwiceTheRememberedCorrectionsFallsBackToTheNewest) {
  const int n = 6;
  const Matrix near = randomVorticity(n, 41), step = randomVorticity(n, 42);
  CorrectionPredictor<Matrix> predictor;
  Matrix newest;
  for (int k = 0; k < 12; ++k) {
    newest = std::pow(3.0, k) * step;
    predictor.remember(near + newest, near);
  }
  Matrix guess(n, n);
  predictor.predict(near, guess);
  EXPECT_LT((guess - (near + newest)).norm(), 1e-12 * newest.norm());
}

}  // namespace correction_predictor_tests
}  // namespace ddb::test
