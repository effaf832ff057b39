// A matrix backend without element access (docs/design/matrix-backend.md): OpaqueMatrix keeps its
// entries private and MatrixBackend<OpaqueMatrix> implements the contract by the dense
// backend's functions on them, so a formula that reached past the backend to an entry would
// not compile. On SU(N) with these matrices (SUNOn<OpaqueMatrix>) the library's own classes
// compile and run: the fluid as a LiePoissonSystem whose Hamiltonian is the test's kernel,
// every method of the method table's kBackendMatrixGroups family built by makeMethod (the
// Legendre solver with its predictor, certified frozen solution and Newton–Krylov fallback,
// the exponential's sweep in the backend's eigenbasis, the transports and the conjugations),
// integrate() and Relaxation with its step control, probe and record, and the Newton search;
// they take the dense backend's bits state by state. The other methods are refused by name.
// The magnetic fluid on DualMatrix<OpaqueMatrix>, whose parts' eigenbasis has no coordinates of
// its own (as the CUDA backend's: cuda/cuda_zeitlin_mhd.h), runs every method of the dense
// magnetic fluid but the exponential ones, and the Newton search, with the dense bits.
#include <ddb/core/matrix_backend.h>
#include <ddb/core/skew_hermitian_eigenbasis.h>
#include <ddb/groups/sun.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <gmock/gmock.h>

#include <complex>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

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

  /// The dense eigenbasis on the entries.
  class Eigenbasis {
   public:
    bool compute(const X& x) { return basis_.compute(x.entries_); }
    double adRadius() const { return basis_.adRadius(); }
    void apply(PhaseFunction f, double scale, const X& in, X& out) {
      basis_.apply(f, scale, in.entries_, out.entries_);
    }
    const Eigen::VectorXd& phases() const { return basis_.phases(); }
    void diagonalPhasesOf(const X& y, Eigen::VectorXd& out) {
      basis_.diagonalPhasesOf(y.entries_, out);
    }
    template <class Weight>
    void setWeights(const Weight& weight) {
      basis_.setWeights(weight);
    }
    void applyWeights(const X& in, X& out) { basis_.applyWeights(in.entries_, out.entries_); }

   private:
    Dense::Eigenbasis basis_;
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
  static void multiplyAdd(double s, const X& a, const X& b, X& out) {
    Dense::multiplyAdd(s, a.entries_, b.entries_, out.entries_);
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
  static bool allFinite(const X& x) { return Dense::allFinite(x.entries_); }
  static void flushSubnormals(X& x) { Dense::flushSubnormals(x.entries_); }
  static bool isZero(const X& x) { return Dense::isZero(x.entries_); }
  template <class Indices, class Out>
  static void sampleEntries(const X& x, const Indices& indices, Out& out) {
    Dense::sampleEntries(x.entries_, indices, out);
  }
  static void save(BinaryRecordWriter& out, const X& x) { Dense::save(out, x.entries_); }
  static void load(BinaryRecordReader& in, X& x) { Dense::load(in, x.entries_); }
};

/// The test's kernels on the entries: states in and out, and the fluid's Hamiltonian (a
/// backend's system brings its own, as the distributed fluid its Poisson solve).
struct OpaqueKernels {
  static OpaqueMatrix wrap(Eigen::MatrixXcd entries) {
    OpaqueMatrix x;
    x.entries_ = std::move(entries);
    return x;
  }
  static const Eigen::MatrixXcd& reveal(const OpaqueMatrix& x) { return x.entries_; }
  static Eigen::MatrixXcd& reveal(OpaqueMatrix& x) { return x.entries_; }
};

namespace opaque_backend_tests {

/// SU(N) on opaque matrices: the methods see nothing but MatrixBackend<OpaqueMatrix>.
using OpaqueSUN = SUNOn<OpaqueMatrix>;

/// Zeitlin's Hamiltonian on opaque matrices: the dense one's kernels on the entries.
class OpaqueZeitlinHamiltonian final : public Hamiltonian<OpaqueSUN> {
 public:
  explicit OpaqueZeitlinHamiltonian(Eigen::Index n) : dense_(n) {}
  double value(const OpaqueMatrix& W) const override { return dense_.value(in(W)); }
  OpaqueMatrix gradient(const OpaqueMatrix& W) const override {
    return OpaqueKernels::wrap(dense_.gradient(in(W)));
  }
  OpaqueMatrix hessianTimes(const OpaqueMatrix& W, const OpaqueMatrix& V) const override {
    return OpaqueKernels::wrap(dense_.hessianTimes(in(W), in(V)));
  }
  void gradientInto(const OpaqueMatrix& W, OpaqueMatrix& out) const override {
    dense_.gradientInto(in(W), OpaqueKernels::reveal(out));
  }
  void hessianTimesInto(const OpaqueMatrix& W, const OpaqueMatrix& V,
                        OpaqueMatrix& out) const override {
    dense_.hessianTimesInto(in(W), in(V), OpaqueKernels::reveal(out));
  }

 private:
  static const Eigen::MatrixXcd& in(const OpaqueMatrix& x) { return OpaqueKernels::reveal(x); }
  ZeitlinHamiltonian dense_;
};

std::shared_ptr<const LiePoissonSystem<OpaqueSUN>> makeOpaqueZeitlinFluid(Eigen::Index n,
                                                                          double alpha) {
  return makeLiePoissonSystem("zeitlin", std::make_shared<const OpaqueZeitlinHamiltonian>(n),
                              std::make_shared<const ScaledIdentityMetric<OpaqueSUN>>(alpha));
}

bool sameBits(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(a(0)) * a.size()) == 0;
}
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Every accepted state of a relaxation: its record and the state.
template <class G>
struct Record {
  std::vector<RelaxState> states;
  std::vector<Eigen::MatrixXcd> matrices;
  RelaxStop stop = RelaxStop::kFailure;
};

template <class G, class Reveal>
Record<G> relaxAndRecord(Relaxation<G>& relaxation, Reveal&& reveal) {
  Record<G> record;
  do {
    record.states.push_back(relaxation.state());
    record.matrices.push_back(reveal(relaxation.current()));
  } while (relaxation.advance());
  record.stop = relaxation.result().stop;
  return record;
}

void expectSameRecords(const Record<SUN>& dense, const Record<OpaqueSUN>& opaque,
                       const std::string& what) {
  ASSERT_EQ(opaque.states.size(), dense.states.size()) << what;
  EXPECT_EQ(opaque.stop, dense.stop) << what;
  for (std::size_t k = 0; k < dense.states.size(); ++k) {
    const RelaxState &a = dense.states[k], &b = opaque.states[k];
    ASSERT_EQ(a.k, b.k) << what;
    for (const auto& [x, y] : {std::pair{a.t, b.t}, {a.h, b.h}, {a.energy, b.energy}}) {
      EXPECT_TRUE(sameBits(x, y)) << what << ", state " << k;
    }
    EXPECT_TRUE(sameBits(a.residual, b.residual) ||
                (std::isnan(a.residual) && std::isnan(b.residual)))
        << what << ", state " << k;
    ASSERT_TRUE(sameBits(opaque.matrices[k], dense.matrices[k])) << what << ", state " << k;
  }
}

/// Relaxation with every row of the method table that runs on any backend's matrices, on the
/// opaque and the dense fluid from the same W0, state by state to the bit: with a fixed h, and
/// adaptive to a residual tolerance (the step control's energy judge, the probe's residual) for
/// at most adaptive_steps steps.
void expectTheDenseRelaxationsBits(Eigen::Index n, double alpha, double h, int adaptive_steps) {
  const Eigen::MatrixXcd W0 = randomVorticity(n, 9);
  const auto dense_fluid = makeZeitlinFluid(n, alpha);
  const auto opaque_fluid = makeOpaqueZeitlinFluid(n, alpha);
  int rows = 0;
  for (const MethodInfo& m : kMethods) {
    if ((m.groups & kBackendMatrixGroups) == 0) continue;
    ++rows;
    for (const bool adaptive : {false, true}) {
      if (adaptive && !m.keeps_casimirs) continue;  // the apps' rule: --adaptive keeps them
      RelaxOptions options;
      options.max_steps = adaptive ? adaptive_steps : 30;
      options.tolerance = adaptive ? 1e-3 : 0.0;
      options.control.adaptive = adaptive;
      const std::string what = std::string(m.name) + ", N = " + std::to_string(n) +
                               (adaptive ? ", adaptive" : ", fixed h");
      auto dense_method = makeMethod<SUN>(m, dense_fluid);
      auto opaque_method = makeMethod<OpaqueSUN>(m, opaque_fluid);
      Relaxation<SUN> dense(*dense_method, *dense_fluid, W0, h, options);
      Relaxation<OpaqueSUN> opaque(*opaque_method, *opaque_fluid, OpaqueKernels::wrap(W0), h,
                                   options);
      const Record<SUN> a = relaxAndRecord(dense, [](const Eigen::MatrixXcd& W) { return W; });
      const Record<OpaqueSUN> b =
          relaxAndRecord(opaque, [](const OpaqueMatrix& W) { return OpaqueKernels::reveal(W); });
      EXPECT_GT(a.states.size(), 10u) << what;
      expectSameRecords(a, b, what);
    }
  }
  EXPECT_GE(rows, 1);
}

// At N = 16 the step control lowers and raises h in every adaptive run, up to the last steps.
// At N = 33 it changes h for the last time by step 28 in every run but ddb-cay's, ddb-exp's and
// ddb-exp-exact's, which change it throughout (measured over 100 steps): 40 steps there keep
// every change of the others and some of those three's, and spare the costly rest (ddb6-exp's
// 100 steps took 18 s).
TEST(OpaqueBackend, EveryMethodForAnyBackendRelaxesWithTheDenseBackendsBitsAtN16) {
  expectTheDenseRelaxationsBits(16, 0.5, 0.05, 100);
}
TEST(OpaqueBackend, EveryMethodForAnyBackendRelaxesWithTheDenseBackendsBitsAtN33) {
  expectTheDenseRelaxationsBits(33, -0.5, 0.02, 40);
}

// The method table's rows of the kBackendMatrixGroups family build on the opaque group; every
// other row is refused by name, with the methods that do run there.
TEST(OpaqueBackend, TheOtherMethodsAreRefusedByName) {
  const auto fluid = makeOpaqueZeitlinFluid(8, 0.5);
  std::string valid;
  for (const auto& name : methodNames(kBackendMatrixGroups)) {
    valid += (valid.empty() ? "" : ", ") + name;
  }
  for (const MethodInfo& m : kMethods) {
    if ((m.groups & kBackendMatrixGroups) != 0) {
      EXPECT_NE(makeMethod<OpaqueSUN>(m, fluid), nullptr) << m.name;
      continue;
    }
    EXPECT_THAT([&] { makeMethod<OpaqueSUN>(m, fluid); },
                ::testing::ThrowsMessage<InvalidArgument>(::testing::AllOf(
                    ::testing::HasSubstr("method = " + std::string(m.name)),
                    ::testing::HasSubstr("written against the matrix backend alone"),
                    ::testing::EndsWith(": " + valid))))
        << m.name;
  }
}

// The Newton search (OrbitNewton: its brackets, conjugate gradients, line search and
// preconditioner through the backend) takes the dense backend's bits iterate by iterate, and
// lowers the residual (at N = 16 from a random vorticity it takes hundreds of iterations to
// 1e-10, at N = 33 and α < 0 about 60).
TEST(OpaqueBackend, TheNewtonSearchTakesTheDenseBackendsBits) {
  for (const auto& [n, alpha] : {std::pair{Eigen::Index{16}, 0.5}, {Eigen::Index{33}, -0.5}}) {
    const Eigen::MatrixXcd W0 = randomVorticity(n, 9);
    const auto dense_fluid = makeZeitlinFluid(n, alpha);
    const auto opaque_fluid = makeOpaqueZeitlinFluid(n, alpha);
    RelaxOptions options;
    options.newton = true;
    options.tolerance = 1e-10;
    options.max_steps = 60;
    Relaxation<SUN> dense(*dense_fluid, W0, options);
    Relaxation<OpaqueSUN> opaque(*opaque_fluid, OpaqueKernels::wrap(W0), options);
    const Record<SUN> a = relaxAndRecord(dense, [](const Eigen::MatrixXcd& W) { return W; });
    const Record<OpaqueSUN> b =
        relaxAndRecord(opaque, [](const OpaqueMatrix& W) { return OpaqueKernels::reveal(W); });
    const std::string what = "newton, N = " + std::to_string(n);
    EXPECT_TRUE(a.stop == RelaxStop::kSteady || a.stop == RelaxStop::kStepCap) << what;
    ASSERT_GT(a.states.size(), 10u) << what;
    EXPECT_LT(a.states.back().residual, 0.1 * a.states[1].residual) << what;
    expectSameRecords(a, b, what);
  }
}

// Newton–Krylov forced from the first iterate (the certificate's fallback) on both backends.
TEST(OpaqueBackend, NewtonKrylovTakesTheDenseBackendsBits) {
  const Eigen::Index n = 16;
  const double h = 0.05;
  const Eigen::MatrixXcd W0 = randomVorticity(n, 9);
  Ddb<Cayley<SUN>> dense(makeZeitlinFluid(n, 0.5), Cayley<SUN>(), LegendreForm::kHamiltonian);
  Ddb<Cayley<OpaqueSUN>> opaque(makeOpaqueZeitlinFluid(n, 0.5), Cayley<OpaqueSUN>(),
                                LegendreForm::kHamiltonian);
  dense.legendreSolver().setStrategy(MatrixLegendreStrategy::kNewtonKrylov);
  opaque.legendreSolver().setStrategy(MatrixLegendreStrategy::kNewtonKrylov);
  Eigen::MatrixXcd W = W0;
  OpaqueMatrix V = OpaqueKernels::wrap(W0);
  int newton = 0;
  for (int k = 0; k < 10; ++k) {
    dense.advance(W, k * h, h);
    opaque.advance(V, k * h, h);
    newton += opaque.legendreSolver().stats().newton;
    ASSERT_TRUE(sameBits(OpaqueKernels::reveal(V), W)) << "step " << k;
  }
  EXPECT_GT(newton, 0);
}

// A relaxation saved part way on the opaque backend and loaded into a fresh one (its method's
// warm start read for the state's shape) takes the uninterrupted run's steps to the bit.
TEST(OpaqueBackend, ARelaxationResumedFromItsRecordContinuesToTheBit) {
  const Eigen::Index n = 12;
  const auto fluid = makeOpaqueZeitlinFluid(n, 0.5);
  const OpaqueMatrix W0 = OpaqueKernels::wrap(randomVorticity(n, 4));
  RelaxOptions options;
  options.max_steps = 40;
  options.tolerance = 1e-9;
  options.control.adaptive = true;
  auto whole_method = makeMethod<OpaqueSUN>("ddb-cay", fluid);
  Relaxation<OpaqueSUN> whole(*whole_method, *fluid, W0, 0.05, options);
  while (whole.advance()) {
  }
  auto first_method = makeMethod<OpaqueSUN>("ddb-cay", fluid);
  Relaxation<OpaqueSUN> first(*first_method, *fluid, W0, 0.05, options);
  for (int k = 0; k < 17; ++k) ASSERT_TRUE(first.advance());
  BinaryRecordWriter out;
  first.save(out);
  BinaryRecordReader in = BinaryRecordReader::unseal(out.sealed());
  auto second_method = makeMethod<OpaqueSUN>("ddb-cay", fluid);
  Relaxation<OpaqueSUN> second(*second_method, *fluid, W0, 0.05, options);
  second.load(in);
  EXPECT_TRUE(in.atEnd());
  while (second.advance()) {
  }
  EXPECT_EQ(second.state().k, whole.state().k);
  EXPECT_TRUE(
      sameBits(OpaqueKernels::reveal(second.current()), OpaqueKernels::reveal(whole.current())));
  EXPECT_TRUE(sameBits(second.state().t, whole.state().t));
}

/// The magnetic fluid's Poisson solve and Laplacian on opaque matrices: the dense ones on the
/// entries (what CudaPoissonSolver is to the CUDA backend).
struct OpaquePoisson {
  HoppeYauLaplacian dense;
  void solve(const OpaqueMatrix& W, OpaqueMatrix& out) const {
    dense.solve(OpaqueKernels::reveal(W), OpaqueKernels::reveal(out));
  }
  void apply(const OpaqueMatrix& P, OpaqueMatrix& out) const {
    dense.apply(OpaqueKernels::reveal(P), OpaqueKernels::reveal(out));
  }
};

using OpaqueDualNumberSUN = DualNumberSUNOn<OpaqueMatrix>;
using OpaqueDual = DualMatrix<OpaqueMatrix>;

OpaqueDual wrap(const DualMatrix<Eigen::MatrixXcd>& mu) {
  return {OpaqueKernels::wrap(mu.real), OpaqueKernels::wrap(mu.eps)};
}
bool sameBits(const OpaqueDual& a, const DualMatrix<Eigen::MatrixXcd>& b) {
  return sameBits(OpaqueKernels::reveal(a.real), b.real) &&
         sameBits(OpaqueKernels::reveal(a.eps), b.eps);
}

// SU(N) ⋉ su(N)* on parts whose eigenbasis works in no coordinates of its own, as the GPU's:
// the dual numbers have no spectral calculus there, so the exponential rows are refused by name;
// every other row of the dense magnetic fluid (the Cayley family, the linearly implicit Cayley
// step with the shift's preconditioner, rk4, lobatto3c) takes the dense magnetic fluid's steps to
// the bit, 20 steps at N = 16 and 33; so does the Newton search, iterate by iterate.
TEST(OpaqueBackend, TheMagneticFluidOnPartsWithoutCoordinatesTakesTheDenseBits) {
  static_assert(!groupHasEigenbasis<OpaqueDualNumberSUN>() &&
                groupHasOrbitPreconditioner<OpaqueDualNumberSUN>());
  for (const Eigen::Index n : {16, 33}) {
    const double alpha = 0.5, h = 0.01;
    const DualMatrix<Eigen::MatrixXcd> mu0 =
        zeitlinMhdState(randomVorticity(n, 1), 0.02 / double(n) * randomVorticity(n, 2));
    const auto dense_mhd = makeZeitlinMhd(n, alpha);
    const auto opaque_mhd =
        makeZeitlinMhdOn<OpaqueMatrix>(OpaquePoisson{HoppeYauLaplacian(n)}, n, alpha);
    int ran = 0;
    for (const MethodInfo& m : kMethods) {
      if (!methodApplies(m, *dense_mhd)) continue;
      const std::string what = std::string(m.name) + ", N = " + std::to_string(n);
      if (needsEigenbasis(m)) {
        EXPECT_FALSE(methodApplies(m, *opaque_mhd)) << what;
        EXPECT_THAT([&] { makeMethod<OpaqueDualNumberSUN>(m, opaque_mhd); },
                    ::testing::ThrowsMessage<InvalidArgument>(
                        ::testing::AllOf(::testing::HasSubstr("method = " + std::string(m.name)),
                                         ::testing::HasSubstr("needs the spectral calculus"))))
            << what;
        continue;
      }
      ASSERT_TRUE(methodApplies(m, *opaque_mhd)) << what;
      ++ran;
      const auto dense_method = makeMethod<DualNumberSUN>(m, dense_mhd);
      const auto opaque_method = makeMethod<OpaqueDualNumberSUN>(m, opaque_mhd);
      DualMatrix<Eigen::MatrixXcd> mu = mu0;
      OpaqueDual nu = wrap(mu0);
      for (int k = 0; k < 20; ++k) {
        dense_method->advance(mu, k * h, h);
        opaque_method->advance(nu, k * h, h);
        ASSERT_TRUE(sameBits(nu, mu)) << what << ", step " << k;
      }
      EXPECT_GT((mu.eps - mu0.eps).norm(), 1e-4 * mu0.eps.norm()) << what;
    }
    // ddb-cay, ddb-cay-implicit, sddb-cay, ddb4-cay, rk4, lobatto3c.
    EXPECT_EQ(ran, 6) << "N = " << n;

    RelaxOptions options;
    options.newton = true;
    options.tolerance = 1e-10;
    options.max_steps = 30;
    Relaxation<DualNumberSUN> dense(*dense_mhd, mu0, options);
    Relaxation<OpaqueDualNumberSUN> opaque(*opaque_mhd, wrap(mu0), options);
    int iterations = 0;
    for (bool more = true; more; ++iterations) {
      ASSERT_TRUE(sameBits(opaque.current(), dense.current())) << "newton, iterate " << iterations;
      ASSERT_TRUE(sameBits(opaque.state().energy, dense.state().energy));
      more = dense.advance();
      ASSERT_EQ(opaque.advance(), more) << "newton, iterate " << iterations;
    }
    EXPECT_EQ(opaque.result().stop, dense.result().stop) << "N = " << n;
    EXPECT_GT(iterations, 10) << "N = " << n;
    EXPECT_LT(dense.state().energy, dense_mhd->energy(mu0)) << "N = " << n;
  }
}

}  // namespace opaque_backend_tests
}  // namespace ddb
