// What a generic formula may ask of a state type without naming a backend: whether it is an
// Eigen matrix or vector (the dense backend's type, whose expressions a formula may write
// directly) and whether its size is fixed at compile time (the small groups' vectors).
// Every other state type is a matrix of some backend, reached through MatrixBackend only
// (docs/design/matrix-backend.md).
#pragma once

#include <Eigen/Core>
#include <type_traits>

namespace ddb {

/// Whether X is an Eigen matrix or vector.
template <class X>
inline constexpr bool isEigenMatrix = std::is_base_of_v<Eigen::MatrixBase<X>, X>;

namespace detail {
template <class X, bool kEigen = isEigenMatrix<X>>
struct HasFixedSize : std::false_type {};
template <class X>
struct HasFixedSize<X, true> : std::bool_constant<X::SizeAtCompileTime != Eigen::Dynamic> {};
}  // namespace detail

/// Whether X's size is fixed at compile time (an Eigen vector of a small group); a backend's
/// matrix has its size at run time.
template <class X>
inline constexpr bool hasFixedSize = detail::HasFixedSize<X>::value;

}  // namespace ddb
