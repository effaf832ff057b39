// One line per registry method (the names of methodNames(); docs/file-formats.md), for
// command-line help and error messages. A method without a line is a test failure
// (tests/test_integrators.cc), so the list cannot drift from the registry.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace ddb {

/// (name, one-line description) in the order of methodNames().
inline const std::vector<std::pair<std::string, std::string>>& methodDescriptions() {
  static const std::vector<std::pair<std::string, std::string>> descriptions{
      {"ddb-cay", "DDB step with the Cayley map (order 1, order 2 at alpha = 0)"},
      {"ddb-exp", "DDB step with exp, dexp^-1 series truncated at order 2 as in the paper"},
      {"ddb-exp-exact", "DDB step with exp and the closed-form dexp^-1"},
      {"sddb-paper-cay", "the paper's symmetric DDB, Cayley (order 1 as written; Lagrangian only)"},
      {"sddb-paper-exp", "the paper's symmetric DDB, exp (order 1 as written; Lagrangian only)"},
      {"sddb-cay", "one-step symmetric DDB, Cayley (order 2)"},
      {"sddb-exp", "one-step symmetric DDB, exp (order 2)"},
      {"ddb4-cay", "triple jump of sddb-cay (order 4)"},
      {"ddb4-exp", "triple jump of sddb-exp (order 4)"},
      {"ddb6-exp", "Yoshida's 7-stage composition of sddb-exp (order 6)"},
      {"rk4", "classical Runge-Kutta, order 4 (does not keep Casimirs)"},
      {"lobatto3c", "Lobatto IIIC, 3 stages, order 4 (does not keep Casimirs)"},
      {"reference", "adaptive Runge-Kutta-Fehlberg 7(8), tolerance 1e-13"}};
  return descriptions;
}

}  // namespace ddb
