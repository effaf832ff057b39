// Whether a group writes the Jacobian ∂/∂x [(dτ^{-1}_x)* μ] of a retraction itself
// (dcayInvDualJacobian, dexpInvDualJacobian): detection only, without Ceres, for
// core/retraction_jacobians.h and for groups composed of groups (groups/semidirect_product.h).
#pragma once

#include <type_traits>
#include <utility>

namespace ddb::detail {

template <class G, class A, class D, class = void>
struct HasDcayInvDualJacobian : std::false_type {};
template <class G, class A, class D>
struct HasDcayInvDualJacobian<G, A, D,
                              std::void_t<decltype(G::dcayInvDualJacobian(
                                  std::declval<const A&>(), std::declval<const D&>()))>>
    : std::true_type {};

template <class G, class A, class D, class = void>
struct HasDexpInvDualJacobian : std::false_type {};
template <class G, class A, class D>
struct HasDexpInvDualJacobian<G, A, D,
                              std::void_t<decltype(G::dexpInvDualJacobian(
                                  std::declval<const A&>(), std::declval<const D&>()))>>
    : std::true_type {};

}  // namespace ddb::detail
