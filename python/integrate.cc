// ddb.integrate(): one method of the table over `steps` steps, the GIL released around the
// C++ loop; every `every`-th state (and the last) written straight into the NumPy result.
#include <ddb/integrators/method_table.h>
#include <ddb/integrators/run.h>

#include <optional>
#include <string>

#include "bindings.h"
#include "errors.h"
#include "states.h"
#include "system.h"

namespace py = pybind11;

namespace ddb::python {

namespace {

template <class G>
py::tuple integrateOn(const SystemPointer<G>& system, Eigen::Index n, const std::string& name,
                      py::handle mu0_object, double h, long steps, long every) {
  const auto method = makeMethod<G>(name, system);
  Dual<G> mu0 = stateFromArray<G>("mu0", mu0_object, n);
  if constexpr (isDynamicGroup<G>) G::requireState("mu0", mu0);
  requirePositive("h", h);
  if (steps < 0) throwInvalid("steps", std::to_string(steps), "must be >= 0");
  if (every < 1) throwInvalid("every", std::to_string(every), "must be >= 1");
  // States 0, every, 2 every, ... and the last one (EveryKth).
  const py::ssize_t kept = steps / every + 1 + (steps % every != 0 ? 1 : 0);
  py::array_t<double> times(kept);
  auto states = stateStack<G>(kept, n);
  double* t_out = times.mutable_data();
  ScalarOf<G>* state_out = states.mutable_data();
  py::ssize_t written = 0;
  std::optional<FailureRecord> failure;
  {
    py::gil_scoped_release release;
    auto sink = [&](long, double t, const Dual<G>& mu) {
      t_out[written] = t;
      writeState<G>(state_out, written, n, mu);
      ++written;
    };
    EveryKth<Dual<G>, decltype(sink)> thinned(every, sink);
    try {
      integrate(*method, mu0, 0.0, h, steps, thinned);
    } catch (const SolveFailure& f) {
      failure = FailureRecord::of(f);
    }
    thinned.finish();
  }
  if (failure) {
    const py::slice prefix(0, written, 1);
    raiseSolveFailure(*failure, times[prefix], states[prefix]);
  }
  return py::make_tuple(times, states);
}

}  // namespace

void bindIntegrate(py::module_& m) {
  m.def(
      "integrate",
      [](const System& system, const std::string& method, py::handle mu0, double h, long steps,
         long every) {
        return system.visit([&](const auto& p) {
          return integrateOn<GroupOf<decltype(p)>>(p, system.n(), method, mu0, h, steps, every);
        });
      },
      py::arg("system"), py::arg("method"), py::arg("mu0"), py::arg("h"), py::arg("steps"),
      py::arg("every") = 1,
      R"doc(Integrates `system` from mu0 at t = 0 with `method` and returns (t, states).

system: a ddb.System (rigid_body, heavy_top, kirchhoff, manakov, zeitlin, user_system).
method: a name of ddb.methods() that applies to the system (system.methods()), e.g.
    "ddb-cay", "sddb-exp", "ddb4-cay", "rk4", "reference".
mu0: the initial state, array-like of the system's state_shape: (3,) on SO3, (6,) on SE3,
    a real skew-symmetric (N, N) matrix on SO(N), a complex skew-Hermitian traceless one on
    SU(N); finite. Copied once.
h: the step size, finite and > 0.
steps: the number of steps, >= 0; the run ends at t = steps * h.
every: keep every `every`-th state (k = 0, every, 2 every, ...) and the last one; >= 1.

Returns t, an array (k,) of times, and states, an array (k, 3), (k, 6) or (k, N, N)
(real on SO3, SE3, SO(N), complex on SU(N)), each state written straight from the C++ loop
into it (one copy per kept state, none per step). The GIL is released during the loop
(a system defined in Python takes it back for each call of its functions).

Raises ValueError naming the parameter for bad arguments (unknown or inapplicable method,
non-finite or wrongly shaped mu0, h <= 0, steps < 0, every < 1) and ddb.SolveFailure when a
step fails (an implicit solve that did not converge, a non-finite state, ...): its fields
say where (step, t, h, residual) and its `times`, `states` hold what was computed before.)doc");
}

}  // namespace ddb::python
