// Gauss–Legendre quadrature on [0, 1], for the integrals over t ∈ [0, 1] of the dual-number
// eigenbasis (core/dual_eigenbasis.h): the Q-node rule's nodes by Newton's iteration on the
// Legendre polynomial P_Q, and the composite rule whose error bound for an integrand of a given
// frequency is below the rounding of the result.
#pragma once

#include <array>
#include <cmath>

namespace ddb::detail {

/// The Q-node Gauss–Legendre rule on [0, 1], 2 ≤ Q ≤ kMaxNodes: exact for polynomials of degree
/// 2Q − 1.
struct GaussLegendreRule {
  static constexpr int kMaxNodes = 12;
  int count = 0;
  std::array<double, kMaxNodes> nodes{}, weights{};

  explicit GaussLegendreRule(int q) : count(q) {
    const double pi = std::acos(-1.0);
    for (int i = 0; i < (q + 1) / 2; ++i) {
      // Tricomi's approximation of the i-th root of P_q on [−1, 1], then Newton's iteration.
      double x = std::cos(pi * (i + 0.75) / (q + 0.5)), derivative = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double value = 0.0;
        legendre(q, x, value, derivative);
        const double step = value / derivative;
        x -= step;
        if (std::abs(step) <= 1e-16) break;
      }
      double value = 0.0;
      legendre(q, x, value, derivative);
      // The weight on [−1, 1] is 2/((1 − x²)P_q'(x)²); on [0, 1] half of it.
      const double weight = 1.0 / ((1.0 - x * x) * derivative * derivative);
      nodes[i] = 0.5 * (1.0 - x);
      nodes[q - 1 - i] = 0.5 * (1.0 + x);
      weights[i] = weights[q - 1 - i] = weight;
    }
  }

 private:
  // P_q(x) and P_q'(x) (|x| < 1) by the three-term recurrence.
  static void legendre(int q, double x, double& value, double& derivative) {
    double previous = 1.0, current = x;  // P_0, P_1
    for (int k = 2; k <= q; ++k) {
      const double next = ((2 * k - 1) * x * current - (k - 1) * previous) / k;
      previous = current;
      current = next;
    }
    value = current;
    derivative = q * (x * current - previous) / (x * x - 1.0);
  }
};

/// A composite Gauss–Legendre rule on [0, 1]: `panels` equal panels of `nodes` nodes each.
struct CompositeRule {
  int panels = 1;
  int nodes = 2;
};

/// The rule for ∫₀¹ t·e(t) dt with |e⁽ᵏ⁾| ≤ cᵏ max|e| (e of frequency at most c ≥ 0): panels of
/// length L with cL ≤ 4, each with the fewest nodes whose error bound, relative to max|e|,
///   (Q!)⁴ / ((2Q + 1) ((2Q)!)³) · ((cL)^{2Q} + 2Q (cL)^{2Q−1})
/// (the Q-node rule's remainder with |(t e)^{(2Q)}| ≤ c^{2Q} + 2Q c^{2Q−1} on a panel, summed over
/// the panels), is below 1e-17. Ten nodes suffice at cL = 4.
inline CompositeRule compositeRuleFor(double c) {
  CompositeRule rule;
  rule.panels = c > 4.0 ? static_cast<int>(std::ceil(c / 4.0)) : 1;
  const double local = c / rule.panels;
  if (local == 0.0) return rule;  // the integrand is linear in t: two nodes are exact
  for (rule.nodes = 2; rule.nodes < GaussLegendreRule::kMaxNodes; ++rule.nodes) {
    const int q = rule.nodes;
    const double log_factor =
        4.0 * std::lgamma(q + 1.0) - std::log(2.0 * q + 1.0) - 3.0 * std::lgamma(2.0 * q + 1.0);
    const double log_bound = log_factor + (2 * q - 1) * std::log(local) + std::log(local + 2.0 * q);
    if (log_bound < std::log(1e-17)) break;
  }
  return rule;
}

}  // namespace ddb::detail
