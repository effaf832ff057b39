// States between NumPy and Eigen (docs/guide/python.md, "Copies"). A state of SO(3) is an array
// of shape (3,), of SE(3) (6,), of SO(N) a real (N, N) array, of SU(N) a complex (N, N)
// one, of SU(N) ⋉ su(N)* (the magnetic fluid) a complex (2, N, N) one, [W, Θ] as quflow's MHD
// state (DualMatrix's ε-part, then its 1-part); a stack of k states has a leading axis k. Every
// conversion copies: into an Eigen object that the integrator owns and steps in place, and out into
// NumPy's row-major layout from Eigen's column-major one.
#pragma once

#include <ddb/core/dual_matrix.h>
#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

namespace ddb::python {

template <class G>
using Dual = typename G::template Dual<double>;
template <class G>
using ScalarOf = typename Dual<G>::Scalar;
template <class G>
using RowMajorState = Eigen::Matrix<ScalarOf<G>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Whether G's states are dual-number matrices (SU(N) ⋉ su(N)*): two N x N parts.
template <class G>
inline constexpr bool kTwoParts = std::is_same_v<Dual<G>, DualMatrix<Eigen::MatrixXcd>>;

/// The shape of one state: (d,) on a fixed-size group, (N, N) on a matrix group, (2, N, N) on
/// SU(N) ⋉ su(N)*.
template <class G>
std::vector<pybind11::ssize_t> stateShape(Eigen::Index n) {
  if constexpr (kTwoParts<G>) {
    return {2, n, n};
  } else if constexpr (isDynamicGroup<G>) {
    return {n, n};
  } else {
    return {Dual<G>::RowsAtCompileTime};
  }
}

/// The state whose entries start at `data` in stateShape<G>(n)'s row-major order (a copy).
template <class G>
Dual<G> stateAt(const ScalarOf<G>* data, Eigen::Index n) {
  using Parts = Eigen::Map<const RowMajorState<G>>;
  if constexpr (kTwoParts<G>) {
    return {Parts(data + n * n, n, n), Parts(data, n, n)};  // [W, Θ]: ε-part first
  } else if constexpr (isDynamicGroup<G>) {
    return Parts(data, n, n);
  } else {
    return Eigen::Map<const Dual<G>>(data);
  }
}

/// "(3,)", "(4, 4)": a shape as NumPy prints it; a negative extent prints as k.
inline std::string shapeText(const std::vector<pybind11::ssize_t>& shape) {
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    text += (i ? ", " : "") + (shape[i] < 0 ? std::string("k") : std::to_string(shape[i]));
  }
  return text + (shape.size() == 1 ? ",)" : ")");
}

/// `object` as a C-contiguous array of G's scalar, its dtype checked (a complex array for a
/// real group is refused, not truncated); InvalidArgument naming `name` otherwise.
template <class G>
pybind11::array_t<ScalarOf<G>, pybind11::array::c_style> asStateArray(const std::string& name,
                                                                      pybind11::handle object) {
  namespace py = pybind11;
  const py::array array = py::array::ensure(object);
  if (!array) throwInvalid(name, std::string(py::str(py::type::of(object))), "must be an array");
  const char kind = array.dtype().kind();
  const bool complex_group = Eigen::NumTraits<ScalarOf<G>>::IsComplex;
  if (!(kind == 'f' || kind == 'i' || kind == 'u' || (complex_group && kind == 'c'))) {
    throwInvalid(name, "an array of dtype " + std::string(py::str(array.dtype())),
                 complex_group ? "must be real or complex" : "must be real");
  }
  return py::array_t<ScalarOf<G>, py::array::c_style | py::array::forcecast>::ensure(array);
}

/// One state from `object`, of shape stateShape<G>(n), its entries unchecked (a copy).
template <class G>
Dual<G> stateOfShape(const std::string& name, pybind11::handle object, Eigen::Index n) {
  const auto array = asStateArray<G>(name, object);
  const std::vector<pybind11::ssize_t> shape(array.shape(), array.shape() + array.ndim());
  if (shape != stateShape<G>(n)) {
    throwInvalid(name, "an array of shape " + shapeText(shape),
                 "must have shape " + shapeText(stateShape<G>(n)));
  }
  return stateAt<G>(array.data(), n);
}

/// One state from `object`, of shape stateShape<G>(n), finite (a copy).
template <class G>
Dual<G> stateFromArray(const std::string& name, pybind11::handle object, Eigen::Index n) {
  Dual<G> state = stateOfShape<G>(name, object, n);
  if constexpr (kTwoParts<G>) {
    requireFinite(name + "[0] (W)", state.eps);
    requireFinite(name + "[1] (Theta)", state.real);
    return state;
  } else {
    return requireFinite(name, state);
  }
}

/// Calls f(state) for one state or each of a stack (shape stateShape<G>(n) or (k, ...)),
/// each a copy; returns whether `object` was a stack.
template <class G, class F>
bool forEachState(const std::string& name, pybind11::handle object, Eigen::Index n, F&& f) {
  const auto array = asStateArray<G>(name, object);
  const std::vector<pybind11::ssize_t> one = stateShape<G>(n);
  const std::vector<pybind11::ssize_t> shape(array.shape(), array.shape() + array.ndim());
  const bool stack = shape.size() == one.size() + 1;
  if (!(shape == one || (stack && std::equal(one.begin(), one.end(), shape.begin() + 1)))) {
    std::vector<pybind11::ssize_t> stacked{-1};
    stacked.insert(stacked.end(), one.begin(), one.end());
    throwInvalid(name, "an array of shape " + shapeText(shape),
                 "must have shape " + shapeText(one) + " or " + shapeText(stacked));
  }
  const pybind11::ssize_t count = stack ? shape[0] : 1;
  const Eigen::Index size =
      stack ? array.size() / std::max<pybind11::ssize_t>(count, 1) : array.size();
  for (pybind11::ssize_t k = 0; k < count; ++k) {
    f(stateAt<G>(array.data() + k * size, n));
  }
  return stack;
}

/// An uninitialised array of `count` states.
template <class G>
pybind11::array_t<ScalarOf<G>> stateStack(pybind11::ssize_t count, Eigen::Index n) {
  std::vector<pybind11::ssize_t> shape{count};
  for (const auto d : stateShape<G>(n)) shape.push_back(d);
  return pybind11::array_t<ScalarOf<G>>(shape);
}

/// Writes `state` as entry k of a stack whose data starts at `data` (no GIL needed).
template <class G>
void writeState(ScalarOf<G>* data, pybind11::ssize_t k, Eigen::Index n, const Dual<G>& state) {
  if constexpr (kTwoParts<G>) {
    Eigen::Map<RowMajorState<G>>(data + 2 * k * n * n, n, n) = state.eps;
    Eigen::Map<RowMajorState<G>>(data + (2 * k + 1) * n * n, n, n) = state.real;
  } else if constexpr (isDynamicGroup<G>) {
    Eigen::Map<RowMajorState<G>>(data + k * n * n, n, n) = state;
  } else {
    Eigen::Map<Dual<G>>(data + k * Dual<G>::RowsAtCompileTime) = state;
  }
}

/// One state as a new array (a copy).
template <class G>
pybind11::array_t<ScalarOf<G>> stateToArray(const Dual<G>& state) {
  Eigen::Index n = 0;
  if constexpr (kTwoParts<G>) {
    n = state.real.rows();
  } else if constexpr (isDynamicGroup<G>) {
    n = state.rows();
  }
  pybind11::array_t<ScalarOf<G>> array(stateShape<G>(n));
  writeState<G>(array.mutable_data(), 0, n, state);
  return array;
}

/// f(state) for one state (a float if `scalar`, else an array (c,)) or for each of a stack
/// of k (an array (k,) or (k, c)).
template <class G, class F>
pybind11::object mapStates(pybind11::handle states, Eigen::Index n, bool scalar, F&& f) {
  std::vector<Eigen::VectorXd> values;
  const bool stack =
      forEachState<G>("states", states, n, [&](const Dual<G>& mu) { values.emplace_back(f(mu)); });
  if (!stack && scalar) return pybind11::float_(values[0](0));
  const auto width = static_cast<pybind11::ssize_t>(values.empty() ? 0 : values[0].size());
  std::vector<pybind11::ssize_t> shape;
  if (stack) shape.push_back(static_cast<pybind11::ssize_t>(values.size()));
  if (!scalar) shape.push_back(width);
  pybind11::array_t<double> out(shape);
  double* data = out.mutable_data();
  for (const auto& v : values) data = std::copy(v.data(), v.data() + v.size(), data);
  return std::move(out);
}

}  // namespace ddb::python
