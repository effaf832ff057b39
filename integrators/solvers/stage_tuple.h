// StageTuple<X, S>: the S stage slopes of an implicit Runge–Kutta step on a matrix group, each
// a matrix of a backend X (core/matrix_backend.h), and MatrixBackend<StageTuple<X, S>>: the
// operations that the stage solver (integrators/methods/matrix_free_runge_kutta.h) and GMRES
// (matrix_free_gmres.h) apply to the tuple, stage by stage through X's backend. The inner
// product is Σ_i Re tr(x_iᴴ y_i), the sum over the stages, and the norms follow it; so the
// stages are solved for on any backend without being laid side by side in one matrix. Only
// these functions are defined: a tuple is not a state.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/matrix_backend.h>

#include <array>
#include <cmath>
#include <string>

namespace ddb {

template <class X, int S>
struct StageTuple {
  using Scalar = typename X::Scalar;
  std::array<X, S> stages;

  X& operator[](int i) { return stages[static_cast<std::size_t>(i)]; }
  const X& operator[](int i) const { return stages[static_cast<std::size_t>(i)]; }
  /// Exchanges the entries of two tuples of one shape, stage by stage.
  void swap(StageTuple& other) {
    for (int i = 0; i < S; ++i) (*this)[i].swap(other[i]);
  }
};

template <class X, int S>
struct MatrixBackend<StageTuple<X, S>> {
  using T = StageTuple<X, S>;
  using B = MatrixBackend<X>;

  static bool sameShape(const T& x, const T& like) { return B::sameShape(x[0], like[0]); }
  static void zeroLike(T& x, const T& like) {
    for (int i = 0; i < S; ++i) B::zeroLike(x[i], like[i]);
  }
  static void setZero(T& x) {
    for (int i = 0; i < S; ++i) B::setZero(x[i]);
  }
  static void scale(double a, const T& x, T& out) {
    for (int i = 0; i < S; ++i) B::scale(a, x[i], out[i]);
  }
  static void divide(T& x, double a) {
    for (int i = 0; i < S; ++i) B::divide(x[i], a);
  }
  static void axpy(double a, const T& x, T& y) {
    for (int i = 0; i < S; ++i) B::axpy(a, x[i], y[i]);
  }
  static void sum(double a, const T& x, double b, const T& y, T& out) {
    for (int i = 0; i < S; ++i) B::sum(a, x[i], b, y[i], out[i]);
  }

  /// Σ_i Re tr(x_iᴴ y_i), the stages' inner products added in stage order.
  static double innerProduct(const T& x, const T& y) {
    double total = 0.0;
    for (int i = 0; i < S; ++i) total += B::innerProduct(x[i], y[i]);
    return total;
  }
  /// (Σ_i ‖x_i‖²)^½.
  static double frobeniusNorm(const T& x) {
    double squares = 0.0;
    for (int i = 0; i < S; ++i) squares += square(B::frobeniusNorm(x[i]));
    return std::sqrt(squares);
  }
  /// (Σ_i ‖x_i − y_i‖²)^½.
  static double frobeniusDistance(const T& x, const T& y) {
    double squares = 0.0;
    for (int i = 0; i < S; ++i) squares += square(B::frobeniusDistance(x[i], y[i]));
    return std::sqrt(squares);
  }
  /// The stages, each as X's backend names it.
  static FormattedValue describe(const T& x) {
    std::string text;
    for (int i = 0; i < S; ++i) {
      text += (i > 0 ? "; " : "") + std::string("stage ") + std::to_string(i + 1) + ": " +
              B::describe(x[i]).text;
    }
    return {text};
  }

 private:
  static double square(double x) { return x * x; }
};

}  // namespace ddb
