// Butcher tableaus as data (GeometricIntegrators.jl style): the classical RK4 and
// the 3-stage Lobatto IIIC method of order 4 (docs/reference/conventions.md §2; Hairer & Wanner II,
// IV.5). The flows are autonomous, so the integrators read a and b only; c completes the tableau
// and the tests check it and the order conditions against the method table's order.
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

inline const ButcherTableau<4> kClassicalRk4{
    "rk4",
    {{{0.0, 0.0, 0.0, 0.0}, {0.5, 0.0, 0.0, 0.0}, {0.0, 0.5, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}}},
    {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6},
    {0.0, 0.5, 0.5, 1.0}};

inline const ButcherTableau<3> kLobattoIIIC3{
    "lobatto3c",
    {{{1.0 / 6, -1.0 / 3, 1.0 / 6}, {1.0 / 6, 5.0 / 12, -1.0 / 12}, {1.0 / 6, 2.0 / 3, 1.0 / 6}}},
    {1.0 / 6, 2.0 / 3, 1.0 / 6},
    {0.0, 0.5, 1.0}};

}  // namespace ddb
