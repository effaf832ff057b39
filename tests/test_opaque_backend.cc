// A matrix backend without element access (docs/matrix-backend.md): OpaqueMatrix keeps its
// entries private and MatrixBackend<OpaqueMatrix> implements the contract by the dense
// backend's functions on them, so a formula that reached past the backend to an entry would
// not compile. The DDB Cayley step, which is written against the backend (the Legendre
// solver with its predictor, certified frozen solution and Newton–Krylov fallback, the
// transport and the conjugations: advanceMatrixDdb), compiles and runs on it and takes the
// dense step's bits, for Zeitlin's fluid on this backend (ZeitlinFluidOnBackend) whose
// Poisson solve is the test's kernel.
#include <ddb/core/matrix_backend.h>
#include <ddb/groups/sun.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_fluid_on_backend.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <complex>
#include <cstring>
#include <utility>

namespace ddb {

/// Entries no formula can reach: only MatrixBackend<OpaqueMatrix> and the test's kernels
/// (OpaqueKernels) see them.
class OpaqueMatrix {
 public:
  using Scalar = std::complex<double>;  // a type, not an entry (the class templates name it)

  OpaqueMatrix() = default;
  void swap(OpaqueMatrix& other) { entries_.swap(other.entries_); }

 private:
  friend struct MatrixBackend<OpaqueMatrix>;
  friend struct OpaqueKernels;
  Eigen::MatrixXcd entries_;
};

/// What a third backend implements, each function by the dense backend's on the entries.
template <>
struct MatrixBackend<OpaqueMatrix> {
  using X = OpaqueMatrix;
  using Dense = MatrixBackend<Eigen::MatrixXcd>;
  using Scalar = Dense::Scalar;

  /// The dense LU on the entries.
  class Lu {
   public:
    bool factor(X& a) { return lu_.factor(a.entries_); }
    void solve(const X& factored, X& b) { lu_.solve(factored.entries_, b.entries_); }

   private:
    Dense::Lu lu_;
  };

  static bool sameShape(const X& x, const X& like) {
    return Dense::sameShape(x.entries_, like.entries_);
  }
  static void zeroLike(X& x, const X& like) { Dense::zeroLike(x.entries_, like.entries_); }
  static Eigen::Index rows(const X& x) { return Dense::rows(x.entries_); }
  static Eigen::Index globalSize(const X& x) { return Dense::globalSize(x.entries_); }

  static void copy(const X& x, X& out) { Dense::copy(x.entries_, out.entries_); }
  static void setZero(X& x) { Dense::setZero(x.entries_); }
  static void scale(double a, const X& x, X& out) { Dense::scale(a, x.entries_, out.entries_); }
  static void divide(X& x, double a) { Dense::divide(x.entries_, a); }
  static void axpy(double a, const X& x, X& y) { Dense::axpy(a, x.entries_, y.entries_); }
  static void sum(double a, const X& x, double b, const X& y, X& out) {
    Dense::sum(a, x.entries_, b, y.entries_, out.entries_);
  }
  static void sum(double a, const X& x, double b, const X& y, double c, const X& z, X& out) {
    Dense::sum(a, x.entries_, b, y.entries_, c, z.entries_, out.entries_);
  }
  static void addSum(double a, const X& x, double b, const X& y, X& out) {
    Dense::addSum(a, x.entries_, b, y.entries_, out.entries_);
  }
  template <class Coefficients, class Term>
  static void addCombination(const Coefficients& c, const Term& term, int count, X& out) {
    Dense::addCombination(
        c, [&](int j) -> const Eigen::MatrixXcd& { return term(j).entries_; }, count, out.entries_);
  }
  static FormattedValue describe(const X& x) { return Dense::describe(x.entries_); }

  static void multiply(const X& a, const X& b, X& out) {
    Dense::multiply(a.entries_, b.entries_, out.entries_);
  }
  static void addAdjoint(double s, const X& x, X& out) {
    Dense::addAdjoint(s, x.entries_, out.entries_);
  }
  static void makeSkewHermitian(X& x) { Dense::makeSkewHermitian(x.entries_); }
  static Scalar trace(const X& x) { return Dense::trace(x.entries_); }
  static void addToDiagonal(X& x, Scalar c) { Dense::addToDiagonal(x.entries_, c); }
  static double frobeniusNorm(const X& x) { return Dense::frobeniusNorm(x.entries_); }
  static double frobeniusDistance(const X& x, const X& y) {
    return Dense::frobeniusDistance(x.entries_, y.entries_);
  }
  static double oneNorm(const X& x) { return Dense::oneNorm(x.entries_); }
  static double innerProduct(const X& x, const X& y) {
    return Dense::innerProduct(x.entries_, y.entries_);
  }
  static bool isZero(const X& x) { return Dense::isZero(x.entries_); }
  template <class Indices, class Out>
  static void sampleEntries(const X& x, const Indices& indices, Out& out) {
    Dense::sampleEntries(x.entries_, indices, out);
  }
  static void save(BinaryRecordWriter& out, const X& x) { Dense::save(out, x.entries_); }
  static void load(BinaryRecordReader& in, X& x) { Dense::load(in, x.entries_); }
};

/// The test's kernels on the entries: states in and out, and the fluid's Poisson solve (a
/// backend of the fluid brings its own, as the distributed one does).
struct OpaqueKernels {
  static OpaqueMatrix wrap(Eigen::MatrixXcd entries) {
    OpaqueMatrix x;
    x.entries_ = std::move(entries);
    return x;
  }
  static const Eigen::MatrixXcd& reveal(const OpaqueMatrix& x) { return x.entries_; }

  struct Laplacian {
    explicit Laplacian(Eigen::Index n) : dense(n) {}
    void solve(const OpaqueMatrix& W, OpaqueMatrix& out) const {
      out.entries_.resize(W.entries_.rows(), W.entries_.cols());
      dense.solve(W.entries_, out.entries_);
    }
    HoppeYauLaplacian dense;
  };
};

namespace {

// Zeitlin's fluid on opaque matrices, with the test's Poisson solve.
using OpaqueZeitlinFluid = ZeitlinFluidOnBackend<OpaqueMatrix, OpaqueKernels::Laplacian>;

bool sameBits(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(a(0)) * a.size()) == 0;
}

// `steps` DDB Cayley steps of size h on both backends, each state compared bit for bit.
void expectTheDenseStepsBits(Eigen::Index n, double alpha, double h, int steps,
                             MatrixLegendreStrategy strategy) {
  const Eigen::MatrixXcd W0 = randomVorticity(n, 9);
  Ddb<Cayley<SUN>> dense(makeZeitlinFluid(n, alpha), Cayley<SUN>(), LegendreForm::kHamiltonian);
  dense.legendreSolver().setStrategy(strategy);
  const OpaqueZeitlinFluid system(OpaqueKernels::Laplacian(n), n, alpha);
  const Cayley<SUN> retraction;
  MatrixLegendreSolver<Cayley<SUN>, OpaqueZeitlinFluid> legendre(
      system, retraction, LegendreForm::kHamiltonian, SolverOptions{});
  legendre.setStrategy(strategy);
  MatrixCayleyTransport<SUN, OpaqueZeitlinFluid> transport;
  Eigen::MatrixXcd W = W0;
  OpaqueMatrix opaque = OpaqueKernels::wrap(W0);
  int newton = 0;
  for (int k = 0; k < steps; ++k) {
    dense.advance(W, k * h, h);
    advanceMatrixDdb<SUN>(system, legendre, transport, opaque, k * h, h);
    newton += legendre.stats().newton;
    ASSERT_TRUE(sameBits(OpaqueKernels::reveal(opaque), W)) << "step " << k;
  }
  if (strategy == MatrixLegendreStrategy::kNewtonKrylov) {
    EXPECT_GT(newton, 0);
  }
}

TEST(OpaqueBackend, TheDdbCayleyStepTakesTheDenseBackendsBits) {
  expectTheDenseStepsBits(16, 0.5, 0.05, 40, MatrixLegendreStrategy::kAuto);
  expectTheDenseStepsBits(33, -0.5, 0.02, 20, MatrixLegendreStrategy::kAuto);
}

TEST(OpaqueBackend, NewtonKrylovTakesTheDenseBackendsBits) {
  expectTheDenseStepsBits(16, 0.5, 0.05, 10, MatrixLegendreStrategy::kNewtonKrylov);
}

}  // namespace
}  // namespace ddb
