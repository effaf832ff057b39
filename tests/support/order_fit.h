// Least-squares log-log slope of error against step size, with the round-off
// plateau dropped (errors below `floor` are not in the asymptotic regime).
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

namespace ddb::test {

struct OrderFit {
  double slope = 0.0;
  int points = 0;
};

inline OrderFit fitOrder(const std::vector<double>& h, const std::vector<double>& error,
                         double floor = 1e-13) {
  std::vector<double> x, y;
  for (size_t i = 0; i < h.size(); ++i) {
    if (error[i] <= floor) continue;
    x.push_back(std::log(h[i]));
    y.push_back(std::log(error[i]));
  }
  OrderFit fit;
  fit.points = static_cast<int>(x.size());
  if (x.size() < 2) return fit;
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    mx += x[i] / x.size();
    my += y[i] / x.size();
  }
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  fit.slope = sxy / sxx;
  return fit;
}

}  // namespace ddb::test
