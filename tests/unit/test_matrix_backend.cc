// The dense matrix backend (core/matrix_backend.h): its element-wise operations against
// their formulas evaluated entry by entry with std::complex's operators, bit for bit (signs
// of zeros included); its reductions against loops over the entries with std::abs and
// std::norm, at ordinary scales and where squares of entries under- or overflow.
#include <ddb/core/matrix_backend.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstring>
#include <limits>
#include <vector>

#include "test_support.h"

namespace ddb::test {
namespace matrix_backend_tests {

using Matrix = Eigen::MatrixXcd;
using B = MatrixBackend<Matrix>;

// The same bits, the signs of zeros included.
template <class X>
bool sameBits(const X& a, const X& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(typename X::Scalar) * a.size()) == 0;
}

// A random matrix with signed zeros, tiny and large entries among ordinary ones, so that a
// shortcut that changed a sign or a rounding would show.
template <class X>
X operand(unsigned seed) {
  std::srand(seed);
  X x = X::Random(37, 29);
  x(0, 0) = typename X::Scalar(-0.0);
  x(1, 0) = typename X::Scalar(0.0);
  x(2, 3) *= 1e-300;
  x(3, 2) *= 1e300;
  return x;
}

// entry(i, j) for every entry: the reference result.
template <class X, class Entry>
X entryByEntry(const X& like, const Entry& entry) {
  X out(like.rows(), like.cols());
  for (Eigen::Index j = 0; j < out.cols(); ++j) {
    for (Eigen::Index i = 0; i < out.rows(); ++i) out(i, j) = entry(i, j);
  }
  return out;
}

template <class X>
void checkElementwiseOperations() {
  using Dense = MatrixBackend<X>;
  const X x = operand<X>(11), y = operand<X>(12), z = operand<X>(13), w = operand<X>(14);
  const std::array<double, 4> coefficients{1.0, -1.0, 0.3, -2.5};
  X out;
  Dense::copy(x, out);
  EXPECT_TRUE(sameBits(out, x));
  Dense::setZero(out);
  EXPECT_TRUE(sameBits(out, X(X::Zero(x.rows(), x.cols()))));
  for (const double a : coefficients) {
    Dense::scale(a, x, out);
    EXPECT_TRUE(sameBits(out, entryByEntry(x, [&](auto i, auto j) { return a * x(i, j); })))
        << "scale " << a;
    out = y;
    Dense::axpy(a, x, out);
    EXPECT_TRUE(
        sameBits(out, entryByEntry(x, [&](auto i, auto j) { return y(i, j) + a * x(i, j); })))
        << "axpy " << a;
    out = x;
    Dense::divide(out, a);
    EXPECT_TRUE(sameBits(out, entryByEntry(x, [&](auto i, auto j) { return x(i, j) / a; })))
        << "divide " << a;
    for (const double b : coefficients) {
      Dense::sum(a, x, b, y, out);
      EXPECT_TRUE(
          sameBits(out, entryByEntry(x, [&](auto i, auto j) { return a * x(i, j) + b * y(i, j); })))
          << "sum " << a << ", " << b;
      out = w;
      Dense::addSum(a, x, b, y, out);
      EXPECT_TRUE(sameBits(
          out,
          entryByEntry(x, [&](auto i, auto j) { return w(i, j) + (a * x(i, j) + b * y(i, j)); })))
          << "addSum " << a << ", " << b;
      for (const double c : coefficients) {
        Dense::sum(a, x, b, y, c, z, out);
        EXPECT_TRUE(sameBits(
            out, entryByEntry(
                     x, [&](auto i, auto j) { return a * x(i, j) + b * y(i, j) + c * z(i, j); })))
            << "sum " << a << ", " << b << ", " << c;
      }
    }
  }
  // Operands that are the result, as GMRES writes r ← b − r and the groups x ← a·x.
  out = y;
  Dense::sum(1.0, x, -1.0, out, out);
  EXPECT_TRUE(sameBits(out, entryByEntry(x, [&](auto i, auto j) { return x(i, j) - y(i, j); })));
  out = y;
  Dense::scale(0.3, out, out);
  EXPECT_TRUE(sameBits(out, entryByEntry(x, [&](auto i, auto j) { return 0.3 * y(i, j); })));
  // The predictor's combination, added term by term in order.
  const std::vector<const X*> terms{&x, &y, &z};
  const Eigen::Vector3d c(0.7, -1.0, 1e-3);
  out = w;
  Dense::addCombination(
      c, [&](int j) -> const X& { return *terms[std::size_t(j)]; }, 3, out);
  EXPECT_TRUE(sameBits(out, entryByEntry(x, [&](auto i, auto j) {
                         return ((w(i, j) + c(0) * x(i, j)) + c(1) * y(i, j)) + c(2) * z(i, j);
                       })));
}

TEST(MatrixBackend, ElementwiseOperationsAreTheirFormulasEntryByEntryBitForBit) {
  checkElementwiseOperations<Eigen::MatrixXcd>();
  checkElementwiseOperations<Eigen::MatrixXd>();
}

TEST(MatrixBackend, OneNormIsTheLargestColumnSumOfModuliAtEveryScale) {
  std::srand(7);
  const Matrix base = Matrix::Random(37, 23);
  // 1e-170: |z|² underflows to 0; 1e170: it overflows to inf. Mixed: one huge column
  // beside ordinary ones, and ordinary entries beside subnormal-squared ones.
  for (const double scale : {1.0, 1e-3, 1e3, 1e-170, 1e170, 1e-300, 1e300}) {
    const Matrix x = scale * base;
    const double expected = oneNormByLoops(x);
    EXPECT_NEAR(B::oneNorm(x), expected, 1e-14 * expected) << "scale " << scale;
  }
  Matrix mixed = base;
  mixed.col(3) *= 1e200;
  EXPECT_NEAR(B::oneNorm(mixed), oneNormByLoops(mixed), 1e-14 * oneNormByLoops(mixed));
  mixed = base;
  mixed.col(5) *= 1e-200;
  EXPECT_NEAR(B::oneNorm(mixed), oneNormByLoops(mixed), 1e-14 * oneNormByLoops(mixed));
  EXPECT_EQ(B::oneNorm(Matrix::Zero(4, 4)), 0.0);
  Matrix infinite = base;
  infinite(2, 2) = {INFINITY, 0.0};
  EXPECT_EQ(B::oneNorm(infinite), INFINITY);
  infinite(2, 2) = {NAN, 0.0};
  EXPECT_TRUE(std::isnan(B::oneNorm(infinite)));
}

// multiplyAdd against its formula out + s·(x y) with the product summed entry by entry in long
// double: a GEMM's rounding differs from a loop's, so to 1e-15 of the terms' size.
TEST(MatrixBackend, MultiplyAddIsTheProductAccumulatedIntoOut) {
  std::srand(3);
  const Matrix x = Matrix::Random(13, 11), y = Matrix::Random(11, 9), start = Matrix::Random(13, 9);
  for (const double s : {1.0, -1.0, 0.3}) {
    Matrix out = start;
    B::multiplyAdd(s, x, y, out);
    for (Eigen::Index j = 0; j < out.cols(); ++j) {
      for (Eigen::Index i = 0; i < out.rows(); ++i) {
        std::complex<long double> product = 0;
        long double size = std::abs(start(i, j));
        for (Eigen::Index k = 0; k < x.cols(); ++k) {
          product += std::complex<long double>(x(i, k)) * std::complex<long double>(y(k, j));
          size += std::abs(x(i, k)) * std::abs(y(k, j));
        }
        const std::complex<long double> expected =
            std::complex<long double>(start(i, j)) + static_cast<long double>(s) * product;
        EXPECT_LE(std::abs(std::complex<long double>(out(i, j)) - expected), 1e-15L * size)
            << "s = " << s << ", entry (" << i << ", " << j << ")";
      }
    }
  }
}

// innerProduct against Re tr(xᴴy) formed as the trace of the product xᴴy, column by column in
// long double (an identity the backend's flat sum of Re·Re + Im·Im does not use): to 1e-15 of
// Σ|x_ij||y_ij|, real and complex, and symmetric in x and y to the bit.
template <class X>
void checkInnerProduct() {
  using Dense = MatrixBackend<X>;
  std::srand(5);
  const X x = X::Random(37, 29), y = X::Random(37, 29);
  std::complex<long double> trace = 0;
  long double size = 0;
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      trace += std::conj(std::complex<long double>(x(i, j))) * std::complex<long double>(y(i, j));
      size += std::abs(std::complex<long double>(x(i, j))) *
              std::abs(std::complex<long double>(y(i, j)));
    }
  }
  EXPECT_LE(std::abs(static_cast<long double>(Dense::innerProduct(x, y)) - trace.real()),
            1e-15L * size);
  EXPECT_EQ(Dense::innerProduct(x, y), Dense::innerProduct(y, x));
  const double squared = Dense::innerProduct(x, x);
  const double norm = Dense::frobeniusNorm(x);
  EXPECT_NEAR(squared, norm * norm, 1e-14 * squared);
  EXPECT_EQ(Dense::innerProduct(x, X::Zero(x.rows(), x.cols())), 0.0);
}

TEST(MatrixBackend, InnerProductIsTheRealPartOfTheTraceOfXAdjointY) {
  checkInnerProduct<Eigen::MatrixXcd>();
  checkInnerProduct<Eigen::MatrixXd>();
}

// flushSubnormals zeroes each subnormal part with its sign and changes no other bit;
// allFinite finds a NaN or an infinity in either part.
TEST(MatrixBackend, FlushSubnormalsAndAllFiniteLookAtEveryPartOfEveryEntry) {
  const double tiny = std::numeric_limits<double>::denorm_min() * 3;
  Matrix x = operand<Matrix>(5);
  Matrix expected = x;
  x(4, 4) = {tiny, 1.0};
  expected(4, 4) = {0.0, 1.0};
  x(5, 6) = {2.0, -tiny};
  expected(5, 6) = {2.0, -0.0};
  x(6, 5) = {-std::numeric_limits<double>::min(), tiny};  // the least normal stays
  expected(6, 5) = {-std::numeric_limits<double>::min(), 0.0};
  B::flushSubnormals(x);
  EXPECT_TRUE(sameBits(x, expected));
  EXPECT_TRUE(B::allFinite(x));
  for (const std::complex<double> bad :
       {std::complex<double>(NAN, 0.0), std::complex<double>(0.0, INFINITY),
        std::complex<double>(-INFINITY, 1.0)}) {
    Matrix y = x;
    y(7, 2) = bad;
    EXPECT_FALSE(B::allFinite(y)) << bad;
  }
  Eigen::MatrixXd real = Eigen::MatrixXd::Constant(3, 3, -tiny);
  MatrixBackend<Eigen::MatrixXd>::flushSubnormals(real);
  EXPECT_TRUE(sameBits(real, Eigen::MatrixXd(Eigen::MatrixXd::Constant(3, 3, -0.0))));
}

}  // namespace matrix_backend_tests
}  // namespace ddb::test
