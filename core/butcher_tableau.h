// A Butcher tableau as data (GeometricIntegrators.jl style): a, b and c of an S-stage
// Runge–Kutta method (Hairer & Wanner II, IV.5). The flows are autonomous, so the integrators
// read a and b only; c completes the tableau and the tests check it and the order conditions
// against the method table's order. In core because a system evaluates an explicit tableau's
// stages itself (core/explicit_runge_kutta_sweep.h); the library's tableaus are in
// integrators/methods/butcher_tableau.h.
#pragma once

#include <array>

namespace ddb {

template <int S>
struct ButcherTableau {
  const char* name;
  std::array<std::array<double, S>, S> a;
  std::array<double, S> b;
  std::array<double, S> c;

  bool isExplicit() const {
    for (int i = 0; i < S; ++i)
      for (int j = i; j < S; ++j)
        if (a[i][j] != 0.0) return false;
    return true;
  }
};

}  // namespace ddb
