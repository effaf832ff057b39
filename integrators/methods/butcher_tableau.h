// The library's Butcher tableaus (core/butcher_tableau.h): the classical RK4 and the 3-stage
// Lobatto IIIC method of order 4 (docs/reference/conventions.md §2; Hairer & Wanner II, IV.5).
#pragma once

#include <ddb/core/butcher_tableau.h>

namespace ddb {

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
