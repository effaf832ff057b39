// Scalar-generic helpers: the same formula runs on double and on ceres::Jet
// (possibly nested), as in Sophus. Jet is only declared here (as Ceres's own jet_fwd.h declares
// it): a group's header does not include Ceres; a program that differentiates includes
// <ceres/jet.h> (core/autodiff.h, core/detail/jet_jacobian.h do).
#pragma once

#include <cmath>
#include <complex>

namespace ceres {
template <typename T, int N>
struct Jet;
}  // namespace ceres

namespace ddb {

/// Number of derivative directions carried by a scalar type (0 for double).
template <class T>
struct JetTraits {
  static constexpr int kDirections = 0;
};
template <class T, int N>
struct JetTraits<ceres::Jet<T, N>> {
  static constexpr int kDirections = N;
};

/// The value of a scalar with every derivative part dropped (recursively for
/// nested Jets). Used for branch decisions, which must not depend on derivatives.
inline double scalarPart(double x) { return x; }
inline std::complex<double> scalarPart(const std::complex<double>& x) { return x; }
template <class T, int N>
double scalarPart(const ceres::Jet<T, N>& x) {
  return scalarPart(x.a);
}

/// The real part of a real or complex scalar (std::real has no Jet overload).
template <class T>
T realPart(const T& x) {
  return x;
}
template <class T>
T realPart(const std::complex<T>& x) {
  return x.real();
}

/// A constant of scalar type T (double or a possibly nested Jet). Nested Jets have
/// no constructor from double, so constants in scalar-generic code are lifted with
/// constant<T>(0.5) rather than T(0.5).
template <class T>
T constant(double x) {
  if constexpr (JetTraits<T>::kDirections == 0) {
    return T(x);
  } else {
    return T(constant<decltype(T().a)>(x));
  }
}

}  // namespace ddb
