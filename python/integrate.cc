// ddb.integrate(): one method of the table over `steps` steps, the GIL released around the
// C++ loop; every `every`-th state (and the last) written straight into the NumPy result.
// Between steps the loop lets Python's signal handlers run (Ctrl-C ends it), and a Python
// exception that ends it carries the states kept so far, as a SolveFailure does.
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/methods/method_table.h>

#include <chrono>
#include <optional>
#include <string>
#include <type_traits>

#include "arguments.h"
#include "bindings.h"
#include "errors.h"
#include "states.h"
#include "system.h"

namespace py = pybind11;

namespace ddb::python {

namespace {

/// Called after every step of a loop that runs without the GIL: about every kCheckInterval
/// it takes the GIL and runs Python's signal handlers (PyErr_CheckSignals), which otherwise
/// wait for the loop's end, and throws what a handler raised (KeyboardInterrupt for Ctrl-C)
/// as py::error_already_set. The clock is read every `stride_` steps only, the stride adapted
/// so that reads come about kReadInterval apart: a rigid-body step (about 0.1 us) would
/// otherwise pay a read (about 20 ns) each, a fluid step (milliseconds) wait too long for one.
class SignalCheck {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr Clock::duration kCheckInterval = std::chrono::milliseconds(50);
  static constexpr Clock::duration kReadInterval = std::chrono::milliseconds(1);
  static constexpr long kMaxStride = 1L << 20;

  void operator()() {
    if (--countdown_ > 0) return;
    const Clock::time_point now = Clock::now();
    const Clock::duration since_read = now - last_read_;
    last_read_ = now;
    if (since_read < kReadInterval && stride_ < kMaxStride) stride_ *= 2;
    if (since_read > 8 * kReadInterval && stride_ > 1) stride_ /= 2;
    countdown_ = stride_;
    if (now - last_check_ < kCheckInterval) return;
    last_check_ = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }

 private:
  long stride_ = 1, countdown_ = 1;
  Clock::time_point last_read_ = Clock::now(), last_check_ = last_read_;
};

template <class G>
py::tuple integrateOn(const System& owner, const SystemPointer<G>& system, Eigen::Index n,
                      const std::string& name, py::handle mu0_object, double h, long steps,
                      long every) {
  auto method = makeMethod<G>(name, system);
  if constexpr (std::is_same_v<G, SUN>) method = owner.withExactFlows(std::move(method));
  Dual<G> mu0 = stateFromArray<G>("mu0", mu0_object, n);
  if constexpr (kTwoParts<G>) {
    G::requireState("mu0[1] (Theta)", "mu0[0] (W)", mu0);
  } else if constexpr (isDynamicGroup<G>) {
    G::requireState("mu0", mu0);
  }
  requirePositive("h", h);
  // States 0, every, 2 every, ... and the last one (EveryKth).
  const py::ssize_t kept = steps / every + 1 + (steps % every != 0 ? 1 : 0);
  py::array_t<double> times(kept);
  auto states = stateStack<G>(kept, n);
  double* t_out = times.mutable_data();
  ScalarOf<G>* state_out = states.mutable_data();
  py::ssize_t written = 0;
  std::optional<FailureRecord> failure;
  // A Python exception that ended the loop: raised by a signal handler or by a Python-defined
  // Hamiltonian (KeyboardInterrupt included, which Python raises inside the user's function).
  std::optional<py::error_already_set> python_error;
  {
    py::gil_scoped_release release;
    auto sink = [&](long, double t, const Dual<G>& mu) {
      t_out[written] = t;
      writeState<G>(state_out, written, n, mu);
      ++written;
    };
    EveryKth<Dual<G>, decltype(sink)> thinned(every, sink);
    SignalCheck check_signals;
    try {
      integrate(*method, mu0, 0.0, h, steps, [&](long k, double t, const Dual<G>& mu) {
        thinned(k, t, mu);
        check_signals();
      });
    } catch (const SolveFailure& f) {
      failure = FailureRecord::of(f);
    } catch (const py::error_already_set& e) {
      python_error = e;
    }
    thinned.finish();
  }
  const py::slice prefix(0, written, 1);
  if (failure) raiseSolveFailure(*failure, times[prefix], states[prefix]);
  if (python_error) {
    python_error->value().attr("times") = times[prefix];
    python_error->value().attr("states") = states[prefix];
    throw *python_error;
  }
  return py::make_tuple(times, states);
}

}  // namespace

void bindIntegrate(py::module_& m) {
  m.def(
      "integrate",
      [](py::handle system, py::handle method, py::handle mu0, py::handle h, py::handle steps,
         py::handle every) {
        if (!py::isinstance<System>(system)) {
          throwInvalid("system", std::string(py::repr(system)),
                       "must be a ddb.System (rigid_body(), zeitlin(), user_system(), ...)");
        }
        const auto& s = system.cast<const System&>();
        const std::string name = textArgument("method", method);
        const double step = realArgument("h", h);
        const long count = integerArgument<long>("steps", steps, 0);
        const long thinning = integerArgument<long>("every", every, 1);
        return s.visit([&](const auto& p) {
          return integrateOn<GroupOf<decltype(p)>>(s, p, s.n(), name, mu0, step, count, thinning);
        });
      },
      py::arg("system"), py::arg("method"), py::arg("mu0"), py::arg("h"), py::arg("steps"),
      py::arg("every") = 1,
      R"doc(Integrates `system` from mu0 at t = 0 with `method` and returns (t, states).

system: a ddb.System (rigid_body, heavy_top, kirchhoff, planar_kirchhoff, manakov, zeitlin,
    zeitlin_mhd, user_system).
method: a name of ddb.methods() that applies to the system (system.methods()), e.g.
    "ddb-cay", "sddb-exp", "ddb4-cay", "rk4", "reference".
mu0: the initial state, array-like of the system's state_shape: (3,) on SO3 and SE2, (6,) on SE3,
    a real skew-symmetric (N, N) matrix on SO(N), a complex skew-Hermitian traceless one on
    SU(N), two such, (2, N, N) [W, Theta], on zeitlin_mhd's SU(N) x| su(N)*; finite. Copied once.
h: the step size, finite and > 0.
steps: the number of steps, >= 0; the run ends at t = steps * h.
every: keep every `every`-th state (k = 0, every, 2 every, ...) and the last one; >= 1.

Returns t, an array (k,) of times, and states, an array (k, 3), (k, 6), (k, N, N) or
(k, 2, N, N) (real on SO3, SE2, SE3, SO(N), complex on SU(N) and SU(N) x| su(N)*), each state written straight from the C++ loop
into it (one copy per kept state, none per step). The GIL is released during the loop
(a system defined in Python takes it back for each call of its functions).

Raises ValueError naming the parameter for bad arguments (a wrong type, an unknown or
inapplicable method, non-finite or wrongly shaped mu0, h <= 0, steps < 0, every < 1) and
ddb.SolveFailure when a step fails (an implicit solve that did not converge, a non-finite
state or result of a Python-defined Hamiltonian, ...): its fields say where (step, t, h,
residual) and its `times`, `states` hold what was computed before.

Ctrl-C (SIGINT, or any signal whose Python handler raises) stops the run between steps,
within about 50 ms: the handler's exception (KeyboardInterrupt) is raised with `times` and
`states` attributes holding the states kept so far, the last one computed included. So is
any exception raised inside a Python-defined Hamiltonian.)doc");
}

}  // namespace ddb::python
