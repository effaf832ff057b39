// GroupTraits: what a group is made of, read from the group alone, and a check of the
// minimum API of core/lie_group.h with one message per missing member, so that a group
// lacking e.g. dualVee fails at the door, not deep inside an integrator's instantiation.
//
// A group is "dynamic" when its algebra elements are runtime-sized N×N matrices
// (kDim == Eigen::Dynamic: SO(N), SU(N)); the integrators choose their matrix-free
// solvers by this trait, never by naming a group.
#pragma once

#include <Eigen/Core>
#include <type_traits>
#include <utility>

namespace ddb {

/// \cond detail
// (Doxygen cannot resolve the detection macros' expressions; detail is not API anyway.)
namespace detail {
template <class, class = void>
struct HasDim : std::false_type {};
template <class G>
struct HasDim<G, std::void_t<decltype(G::kDim), decltype(G::kNumCasimirs)>> : std::true_type {};

template <class, class = void>
struct HasTypes : std::false_type {};
template <class G>
struct HasTypes<
    G, std::void_t<typename G::template Algebra<double>, typename G::template Dual<double>,
                   typename G::template Matrix<double>, typename G::template Casimirs<double>>>
    : std::true_type {};

template <class G>
using A = typename G::template Algebra<double>;
template <class G>
using D = typename G::template Dual<double>;
template <class G>
using M = typename G::template Matrix<double>;

#define DDB_DETECT_STATIC(NAME, EXPR) \
  template <class, class = void>      \
  struct NAME : std::false_type {};   \
  template <class G>                  \
  struct NAME<G, std::void_t<decltype(EXPR)>> : std::true_type {};

DDB_DETECT_STATIC(HasHat, G::hat(std::declval<const A<G>&>()))
DDB_DETECT_STATIC(HasVee, G::vee(std::declval<const M<G>&>()))
DDB_DETECT_STATIC(HasDualHat, G::dualHat(std::declval<const D<G>&>()))
DDB_DETECT_STATIC(HasDualVee, G::dualVee(std::declval<const M<G>&>()))
DDB_DETECT_STATIC(HasExp, G::exp(std::declval<const A<G>&>()))
DDB_DETECT_STATIC(HasLog, G::log(std::declval<const M<G>&>()))
DDB_DETECT_STATIC(HasCasimirs, G::casimirs(std::declval<const D<G>&>()))
#undef DDB_DETECT_STATIC

/// Whether G says that its pairing is not the inner product of its coordinates
/// (`static constexpr bool kIndefinitePairing = true`: SU(N) ⋉ su(N)*, groups/dual_number_sun.h).
template <class, class = void>
struct HasIndefinitePairing : std::false_type {};
template <class G>
struct HasIndefinitePairing<G, std::enable_if_t<G::kIndefinitePairing>> : std::true_type {};
}  // namespace detail
/// \endcond

/// x ← its Riesz representer: the element ν of the same coordinates with
/// innerProduct(ν, η) = ⟨x, η⟩ for every η, ⟨·,·⟩ G's pairing. The identity where the pairing is
/// the inner product of the coordinates; G::rieszMap where G says it is another (SU(N) ⋉ su(N)*
/// swaps the parts, groups/dual_number_sun.h). It turns a differential ⟨g, ·⟩ into the gradient
/// that the solvers' inner product sees (integrators/solvers/orbit_newton.h), and α times it is
/// the metric k♯ = α·I of such a group (core/dissipation_metric.h).
template <class G, class X>
void rieszMapInPlace(X& x) {
  if constexpr (detail::HasIndefinitePairing<G>::value) G::rieszMap(x);
}

/// Compile-time facts about a group G, and the check of its minimum API.
template <class G>
struct GroupTraits {
  static_assert(detail::HasDim<G>::value, "a group must define kDim and kNumCasimirs");
  static_assert(detail::HasTypes<G>::value,
                "a group must define the templates Algebra<T>, Dual<T>, Matrix<T>, Casimirs<T>");
  static_assert(detail::HasHat<G>::value, "a group must define static hat(Algebra) -> Matrix");
  static_assert(detail::HasVee<G>::value, "a group must define static vee(Matrix) -> Algebra");
  static_assert(detail::HasDualHat<G>::value,
                "a group must define static dualHat(Dual) -> Matrix (the Riesz representer)");
  static_assert(detail::HasDualVee<G>::value, "a group must define static dualVee(Matrix) -> Dual");
  static_assert(detail::HasExp<G>::value, "a group must define static exp(Algebra) -> Matrix");
  static_assert(detail::HasLog<G>::value, "a group must define static log(Matrix) -> Algebra");
  static_assert(detail::HasCasimirs<G>::value,
                "a group must define static casimirs(Dual) -> Casimirs");

  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;
  using Matrix = typename G::template Matrix<double>;
  using Scalar = typename Dual::Scalar;  // double, or std::complex<double> for SU(N)
  /// Runtime-sized N×N matrix algebra: matrix-free solvers, workspaces sized from the state.
  static constexpr bool kDynamic = G::kDim == Eigen::Dynamic;
};

template <class G>
inline constexpr bool isDynamicGroup = GroupTraits<G>::kDynamic;

}  // namespace ddb
