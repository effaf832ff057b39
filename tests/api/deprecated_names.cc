// The names and headers kept as deprecated aliases for the one minor version they live
// (CHANGELOG.md, 0.2.0, "Deprecated"; removed in 0.3.0), used so that removing one before then
// fails the build. Compiled with
// -Wno-deprecated-declarations (tests/CMakeLists.txt); no main(): the compile is the test.

#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/solvers/matrix_legendre.h>

// The headers at their paths before 0.2.0 (CHANGELOG.md, "Deprecated"), which warn unless told.
#define DDB_NO_DEPRECATED_HEADER_WARNINGS
#include <ddb/integrators/correction_predictor.h>
#include <ddb/integrators/ddb.h>
#include <ddb/integrators/energy_step_control.h>
#include <ddb/integrators/linearly_implicit_ddb.h>
#include <ddb/integrators/method_table.h>
#include <ddb/integrators/one_step_method.h>
#include <ddb/integrators/orbit_newton.h>
#include <ddb/integrators/orbit_preconditioner.h>
#include <ddb/integrators/relax.h>
#include <ddb/integrators/run.h>
#include <ddb/integrators/steady_state_probe.h>

#include <string>
#include <type_traits>
#include <vector>

namespace {

// Marks its arguments used.
template <class... T>
void use(const T&...) {}

// docs/guide/matrix-groups-and-the-fluid.md (until 0.2.0): matrixGroupMethodNames(), now
// methodNames(kMatrixGroups).
[[maybe_unused]] void methodTableAliases() {
  const std::vector<std::string> names = ddb::matrixGroupMethodNames();
  use(names, static_cast<std::vector<std::string> (*)()>(&ddb::matrixGroupMethodNames));
}

// integrators/solvers/matrix_legendre.h: MatrixLegendreStrategy::kCeres, now kNewtonKrylov
// (Ceres is useCeres(solver) of matrix_legendre_ceres.h).
static_assert(ddb::MatrixLegendreStrategy::kCeres == ddb::MatrixLegendreStrategy::kNewtonKrylov);
[[maybe_unused]] void matrixLegendreAliases() {
  constexpr ddb::MatrixLegendreStrategy strategy = ddb::MatrixLegendreStrategy::kCeres;
  use(strategy);
}

}  // namespace
