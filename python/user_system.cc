// ddb.user_system(): a system whose Hamiltonian is written in Python (H, its gradient and
// optionally its Hessian-vector product), on SO3, SE3, SO(N) or SU(N), with k# = alpha Id
// or alpha diag(metric); every method of the table that applies runs on it. Each call of
// H's functions takes the GIL and copies the state into a new array (docs/guide/python.md).
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lagrangian.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "arguments.h"
#include "bindings.h"
#include "states.h"
#include "system.h"

namespace py = pybind11;

namespace ddb::python {

namespace {

/// A non-finite result of the user's functions is a NonFiniteState (a SolveFailure) naming
/// the function: integrate() then stops at that step and keeps the states before it, where a
/// ValueError would lose them and a NaN passed on would make a garbage trajectory.
template <class G>
class PythonHamiltonian final : public Hamiltonian<G> {
 public:
  PythonHamiltonian(std::string system, py::object value, py::object gradient,
                    py::object hessian_times, Eigen::Index n)
      : system_("user_system '" + std::move(system) + "'"),
        value_(std::move(value)),
        gradient_(std::move(gradient)),
        hessian_times_(std::move(hessian_times)),
        n_(n) {}
  ~PythonHamiltonian() override {
    // The last owner may be a C++ object destroyed without the GIL.
    py::gil_scoped_acquire gil;
    value_ = py::object();
    gradient_ = py::object();
    hessian_times_ = py::object();
  }

  double value(const Dual<G>& mu) const override {
    py::gil_scoped_acquire gil;
    const py::object result = value_(stateToArray<G>(mu));
    double v = 0.0;
    try {
      v = result.cast<double>();
    } catch (const py::cast_error&) {
      throwInvalid("hamiltonian", "a function returning " + std::string(py::repr(result)),
                   "must return a real number");
    }
    return finite("hamiltonian", v);
  }
  Dual<G> gradient(const Dual<G>& mu) const override {
    py::gil_scoped_acquire gil;
    return finite("gradient", stateOfShape<G>("gradient", gradient_(stateToArray<G>(mu)), n_));
  }
  /// The given Hessian-vector product, or the library's central difference of the gradient.
  Dual<G> hessianTimes(const Dual<G>& mu, const Dual<G>& v) const override {
    if (hessian_times_.is_none()) return Hamiltonian<G>::hessianTimes(mu, v);
    py::gil_scoped_acquire gil;
    return finite("hessian_times",
                  stateOfShape<G>("hessian_times",
                                  hessian_times_(stateToArray<G>(mu), stateToArray<G>(v)), n_));
  }

 private:
  double finite(const std::string& function, double result) const {
    if (!std::isfinite(result)) throw NonFiniteState(system_, -1, NAN, NAN, result, function);
    return result;
  }
  Dual<G> finite(const std::string& function, Dual<G> result) const {
    if (!result.allFinite()) throw NonFiniteState(system_, -1, NAN, NAN, result, function);
    return result;
  }

  std::string system_;
  py::object value_, gradient_, hessian_times_;
  Eigen::Index n_;
};

/// `object` if it is callable (or None where `optional`), else InvalidArgument naming `name`.
py::object callableArgument(const std::string& name, py::object object, bool optional = false) {
  if (PyCallable_Check(object.ptr()) == 0 && !(optional && object.is_none())) {
    throwInvalid(name, std::string(py::repr(object)),
                 optional ? "must be callable or None" : "must be callable");
  }
  return object;
}

template <class G>
std::shared_ptr<System> userSystem(const std::string& name, py::object hamiltonian,
                                   py::object gradient, py::object hessian_times, double alpha,
                                   py::handle metric, Eigen::Index n) {
  if constexpr (isDynamicGroup<G>) {
    if (n < 2 || n > G::kMaxN) {
      throwInvalid("N", std::to_string(n), "must be in [2, " + std::to_string(G::kMaxN) + "]");
    }
  } else if (n != 0) {
    throwInvalid("N", std::to_string(n), std::string("is not used on ") + G::kName);
  }
  auto h = std::make_shared<const PythonHamiltonian<G>>(
      name, callableArgument("hamiltonian", std::move(hamiltonian)),
      callableArgument("gradient", std::move(gradient)),
      callableArgument("hessian_times", std::move(hessian_times), true), n);
  if (metric.is_none()) {
    return std::make_shared<System>(
        makeLiePoissonSystem(name, h, std::make_shared<const ScaledIdentityMetric<G>>(alpha)), n);
  }
  if constexpr (isDynamicGroup<G>) {
    throwInvalid("metric", std::string(py::repr(metric)),
                 std::string("must be None on ") + G::kName + " (k# = alpha Id)");
  } else {
    const auto k = vectorArgument<Dual<G>::RowsAtCompileTime>("metric", metric);
    return std::make_shared<System>(
        makeLiePoissonSystem(name, h, std::make_shared<const DiagonalMetric<G>>(alpha, k)), n);
  }
}

}  // namespace

void bindUserSystem(py::module_& m) {
  m.def(
      "user_system",
      [](py::handle group_object, py::object hamiltonian, py::object gradient,
         py::object hessian_times, py::handle alpha_object, py::handle metric, py::handle n_object,
         py::handle name_object) {
        const std::string group = textArgument("group", group_object);
        const double alpha = realArgument("alpha", alpha_object);
        const auto n = integerArgument<Eigen::Index>("N", n_object);
        const std::string name = textArgument("name", name_object);
        if (group == SO3::kName) {
          return userSystem<SO3>(name, hamiltonian, gradient, hessian_times, alpha, metric, n);
        }
        if (group == SE2::kName) {
          return userSystem<SE2>(name, hamiltonian, gradient, hessian_times, alpha, metric, n);
        }
        if (group == SE3::kName) {
          return userSystem<SE3>(name, hamiltonian, gradient, hessian_times, alpha, metric, n);
        }
        if (group == SON::kName) {
          return userSystem<SON>(name, hamiltonian, gradient, hessian_times, alpha, metric, n);
        }
        if (group == SUN::kName) {
          return userSystem<SUN>(name, hamiltonian, gradient, hessian_times, alpha, metric, n);
        }
        throwInvalid("group", group, "expected one of SO3, SE2, SE3, SO(N), SU(N)");
      },
      py::arg("group"), py::arg("hamiltonian"), py::arg("gradient"),
      py::arg("hessian_times") = py::none(), py::arg("alpha") = 0.0, py::arg("metric") = py::none(),
      py::arg("N") = 0, py::arg("name") = "user",
      R"doc(A Lie-Poisson system whose Hamiltonian is written in Python.

group: "SO3" (states (3,)), "SE2" ((3,)), "SE3" ((6,)), "SO(N)" (real (N, N)) or "SU(N)"
    (complex (N, N)).
hamiltonian: H(mu) -> float.
gradient: dH/dmu(mu) -> array of mu's shape. On SO(N), SU(N) the system hands H the state
    projected onto the algebra and projects the gradient (docs/reference/conventions.md §2).
hessian_times: optional (mu, v) -> D^2H(mu)[v]; without it a central difference of
    `gradient` (good to ~4e-11 relative: it costs Newton iterations, not accuracy).
alpha, metric: the dissipation k# = alpha diag(metric) (SO3, SE2, SE3; metric: 3 or 6 numbers
    >= 0), or alpha Id when metric is None (the only choice on SO(N), SU(N)).
N: the matrix size on SO(N), SU(N).
name: the system's name.

Without a Lagrangian, the paper's symmetric variants (sddb-paper-*) do not apply; every
other method does (system.methods()). Each call of H's functions takes the GIL and copies
the state into a new array: see docs/guide/python.md for what that costs per step.)doc");
}

}  // namespace ddb::python
