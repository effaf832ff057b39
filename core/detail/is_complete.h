// kIsComplete<T>: whether T is a complete type at this point of the translation unit, so that a
// header can stop with a message naming what to include or specialise (the method table's
// reference row, a semidirect product's traits) rather than an incomplete-type error deep inside.
#pragma once

#include <type_traits>

namespace ddb::detail {

template <class T, class = void>
inline constexpr bool kIsComplete = false;
template <class T>
inline constexpr bool kIsComplete<T, std::void_t<decltype(sizeof(T))>> = true;

}  // namespace ddb::detail
