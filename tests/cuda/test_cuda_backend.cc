// The CUDA backend (cuda/cuda_backend.h) against the dense backend (core/matrix_backend.h):
// every backend operation (the element-wise ones and the adjoint passes to the bit, the
// products, reductions, LU and the eigenbasis to round-off), the Poisson solve, the transfers and
// records, a run repeated to the bit, then whole relaxations of every method of the method table's
// kBackendMatrixGroups family on Zeitlin's fluid (within 1e-12 of the dense run after 100 steps,
// or 10 times the dense run's own motion from a W0 moved by one ulp where the flow amplifies
// rounding more: GPU reductions and products add in another order) and the spectrum kept over
// 1000 steps at N = 1024, the damped and forced fluid, the magnetic fluid (its Laplacian to the
// bit, every method that runs on SU(N) ⋉ su(N)* following the dense run and keeping the Casimirs),
// and the contexts (cuda/cuda_context.h).
// Without a GPU every test but CudaDevice's and CudaContext's first is skipped, by ctest's skip,
// naming why (GTEST_SKIP).
#include <ddb/core/skew_hermitian_eigenbasis.h>
#include <ddb/cuda/cuda_backend.h>
#include <ddb/cuda/cuda_context.h>
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_poisson_solver.h>
#include <ddb/cuda/cuda_zeitlin_exact_flows.h>
#include <ddb/cuda/cuda_zeitlin_fluid.h>
#include <ddb/cuda/cuda_zeitlin_mhd.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/strang_splitting.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <ddb/systems/zeitlin_step_size.h>
#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "mhd_casimir_drift.h"

namespace ddb {
namespace {

using Matrix = Eigen::MatrixXcd;
using Dense = MatrixBackend<Matrix>;
using Device = MatrixBackend<CudaMatrix>;

#define SKIP_WITHOUT_GPU() \
  if (const auto why = cudaUnavailable()) GTEST_SKIP() << *why

Matrix randomMatrix(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal;
  Matrix m(rows, cols);
  for (Eigen::Index k = 0; k < m.size(); ++k) m(k) = {normal(engine), normal(engine)};
  return m;
}

bool sameBits(const Matrix& a, const Matrix& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(a(0)) * a.size()) == 0;
}

// max |a − b| / max |b|.
double relativeDifference(const Matrix& a, const Matrix& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

constexpr std::array<std::pair<Eigen::Index, Eigen::Index>, 4> kShapes{
    {{1, 1}, {7, 5}, {64, 64}, {100, 37}}};
constexpr std::array<double, 4> kCoefficients{1.0, -1.0, 0.37, -2.5};

TEST(CudaDevice, NamesTheDeviceOrSaysWhyThereIsNone) {
  if (const auto why = cudaUnavailable()) {
    EXPECT_THAT(*why, ::testing::StartsWith("no CUDA device can be used: "));
    return;
  }
  EXPECT_FALSE(cudaDeviceName().empty());
  const CudaMemory memory = cudaMemory();
  EXPECT_GT(memory.total, 0);
  EXPECT_LE(memory.used, memory.total);
}

TEST(CudaBackend, TransfersRoundTripToTheBit) {
  SKIP_WITHOUT_GPU();
  for (const auto& [rows, cols] : kShapes) {
    const Matrix m = randomMatrix(rows, cols, 1);
    const CudaMatrix x = toDevice(m);
    EXPECT_EQ(x.rows(), rows);
    EXPECT_EQ(x.cols(), cols);
    EXPECT_TRUE(sameBits(toHost(x), m));
    const CudaMatrix copied(x);  // device to device
    EXPECT_TRUE(sameBits(toHost(copied), m));
  }
}

// Each element-wise operation takes the dense backend's bits (no fused multiply-add, the
// same expression), for coefficients ±1 (taken as additions there) and others.
TEST(CudaBackend, ElementWiseOperationsTakeTheDenseBackendsBits) {
  SKIP_WITHOUT_GPU();
  for (const auto& [rows, cols] : kShapes) {
    const Matrix x = randomMatrix(rows, cols, 2), y = randomMatrix(rows, cols, 3),
                 z = randomMatrix(rows, cols, 4), start = randomMatrix(rows, cols, 5);
    const CudaMatrix dx = toDevice(x), dy = toDevice(y), dz = toDevice(z);
    for (const double a : kCoefficients) {
      for (const double b : kCoefficients) {
        const double c = a * b - 0.5;
        const auto expectSame = [&](auto denseOp, auto deviceOp, const char* what) {
          Matrix expected = start;
          denseOp(expected);
          CudaMatrix out = toDevice(start);
          deviceOp(out);
          EXPECT_TRUE(sameBits(toHost(out), expected))
              << what << " a = " << a << " b = " << b << ", " << rows << "x" << cols;
        };
        expectSame([&](Matrix& o) { Dense::scale(a, x, o); },
                   [&](CudaMatrix& o) { Device::scale(a, dx, o); }, "scale");
        expectSame([&](Matrix& o) { Dense::divide(o, a); },
                   [&](CudaMatrix& o) { Device::divide(o, a); }, "divide");
        expectSame([&](Matrix& o) { Dense::axpy(a, x, o); },
                   [&](CudaMatrix& o) { Device::axpy(a, dx, o); }, "axpy");
        expectSame([&](Matrix& o) { Dense::sum(a, x, b, y, o); },
                   [&](CudaMatrix& o) { Device::sum(a, dx, b, dy, o); }, "sum");
        expectSame([&](Matrix& o) { Dense::sum(a, x, b, y, c, z, o); },
                   [&](CudaMatrix& o) { Device::sum(a, dx, b, dy, c, dz, o); }, "sum of three");
        expectSame([&](Matrix& o) { Dense::addSum(a, x, b, y, o); },
                   [&](CudaMatrix& o) { Device::addSum(a, dx, b, dy, o); }, "addSum");
        const std::array<double, 3> weights{a, b, c};
        const std::array<const Matrix*, 3> terms{&x, &y, &z};
        const std::array<const CudaMatrix*, 3> device_terms{&dx, &dy, &dz};
        expectSame(
            [&](Matrix& o) {
              Dense::addCombination([&](int j) { return weights[j]; },
                                    [&](int j) -> const Matrix& { return *terms[j]; }, 3, o);
            },
            [&](CudaMatrix& o) {
              Device::addCombination([&](int j) { return weights[j]; },
                                     [&](int j) -> const CudaMatrix& { return *device_terms[j]; },
                                     3, o);
            },
            "addCombination");
        expectSame(
            [&](Matrix& o) {
              Dense::addToDiagonal(o, {a, b});
            },
            [&](CudaMatrix& o) {
              Device::addToDiagonal(o, {a, b});
            },
            "addToDiagonal");
      }
    }
    CudaMatrix zero = toDevice(x);
    Device::setZero(zero);
    EXPECT_TRUE(sameBits(toHost(zero), Matrix::Zero(rows, cols)));
    CudaMatrix shaped;
    Device::zeroLike(shaped, dx);
    EXPECT_TRUE(Device::sameShape(shaped, dx));
    EXPECT_TRUE(sameBits(toHost(shaped), Matrix::Zero(rows, cols)));
    CudaMatrix copy;
    Device::copy(dx, copy);
    EXPECT_TRUE(sameBits(toHost(copy), x));
  }
}

TEST(CudaBackend, AdjointPassesTakeTheDenseBackendsBits) {
  SKIP_WITHOUT_GPU();
  for (const Eigen::Index n : {1, 5, 32, 33, 64, 100}) {
    const Matrix x = randomMatrix(n, n, 6), start = randomMatrix(n, n, 7);
    for (const double s : {1.0, -1.0, 0.5, -3.25}) {
      Matrix expected = start;
      Dense::addAdjoint(s, x, expected);
      CudaMatrix out = toDevice(start);
      Device::addAdjoint(s, toDevice(x), out);
      EXPECT_TRUE(sameBits(toHost(out), expected)) << "addAdjoint, N = " << n << ", s = " << s;
    }
    Matrix expected = x;
    Dense::makeSkewHermitian(expected);
    CudaMatrix skew = toDevice(x);
    Device::makeSkewHermitian(skew);
    const Matrix got = toHost(skew);
    EXPECT_TRUE(sameBits(got, expected)) << "makeSkewHermitian, N = " << n;
    // Entry (j, i) is −conj(entry (i, j)) by value (the diagonal's real part is +0, its
    // mirror's −0).
    EXPECT_TRUE(got == Matrix(-got.adjoint())) << "skew-Hermitian, N = " << n;
  }
  // A rectangular adjoint: out (3×70) += s·xᴴ, x 70×3.
  const Matrix x = randomMatrix(70, 3, 8), start = randomMatrix(3, 70, 9);
  Matrix expected = start;
  Dense::addAdjoint(0.75, x, expected);
  CudaMatrix out = toDevice(start);
  Device::addAdjoint(0.75, toDevice(x), out);
  EXPECT_TRUE(sameBits(toHost(out), expected));
}

// Products (cuBLAS) and reductions (the kernels' tree) to round-off of the values involved.
TEST(CudaBackend, ProductsAndReductionsAgreeWithTheDenseBackend) {
  SKIP_WITHOUT_GPU();
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  for (const Eigen::Index n : {1, 7, 64, 200}) {
    const Matrix a = randomMatrix(n, n, 10), b = randomMatrix(n, n, 11), c = randomMatrix(n, n, 12);
    const CudaMatrix da = toDevice(a), db = toDevice(b);
    // Each entry of a b is a sum of n products: error below n·ε·(|a||b|)_ij.
    const Eigen::MatrixXd bound = (a.cwiseAbs() * b.cwiseAbs()) * (double(n) * 4 * kEps);
    CudaMatrix product;
    Device::multiply(da, db, product);
    EXPECT_TRUE(((toHost(product) - a * b).cwiseAbs().array() <= bound.array()).all()) << n;
    CudaMatrix accumulated = toDevice(c);
    Device::multiplyAdd(-0.5, da, db, accumulated);
    const Matrix expected = c - 0.5 * a * b;
    EXPECT_TRUE(((toHost(accumulated) - expected).cwiseAbs().array() <=
                 (bound + c.cwiseAbs() * 4 * kEps).array())
                    .all())
        << n;

    const double scale = double(n) * 4 * kEps;
    EXPECT_NEAR(std::abs(Device::trace(da) - a.trace()), 0.0,
                scale * a.diagonal().cwiseAbs().sum());
    EXPECT_NEAR(Device::frobeniusNorm(da), a.norm(), scale * a.norm());
    EXPECT_NEAR(Device::frobeniusDistance(da, db), (a - b).norm(), scale * (a - b).norm());
    EXPECT_NEAR(Device::innerProduct(da, db), (a.adjoint() * b).trace().real(),
                scale * a.norm() * b.norm());
    EXPECT_NEAR(Device::oneNorm(da), Dense::oneNorm(a), scale * Dense::oneNorm(a));
  }
  // The trace of a rectangular matrix: its min(rows, cols) diagonal entries.
  const Matrix wide = randomMatrix(7, 5, 26);
  EXPECT_NEAR(std::abs(Device::trace(toDevice(wide)) - wide.trace()), 0.0,
              1e-15 * wide.diagonal().cwiseAbs().sum());
  // The 1-norm of tiny entries, whose squares underflow, by hypot; NaN propagates.
  Matrix tiny = randomMatrix(9, 9, 13) * 1e-200;
  EXPECT_NEAR(Device::oneNorm(toDevice(tiny)), Dense::oneNorm(tiny), 1e-14 * Dense::oneNorm(tiny));
  tiny(4, 5) = {std::nan(""), 0.0};
  EXPECT_TRUE(std::isnan(Device::oneNorm(toDevice(tiny))));
}

TEST(CudaBackend, PredicatesSamplesAndSubnormals) {
  SKIP_WITHOUT_GPU();
  Matrix m = randomMatrix(6, 6, 14);
  EXPECT_TRUE(Device::allFinite(toDevice(m)));
  m(2, 3) = {0.0, std::numeric_limits<double>::infinity()};
  EXPECT_FALSE(Device::allFinite(toDevice(m)));
  Matrix zero = Matrix::Zero(5, 4);
  zero(1, 1) = {-0.0, 0.0};
  EXPECT_TRUE(Device::isZero(toDevice(zero)));
  zero(3, 2) = {0.0, 1e-310};
  EXPECT_FALSE(Device::isZero(toDevice(zero)));
  zero(0, 0) = {std::nan(""), 0.0};
  EXPECT_FALSE(Device::isZero(toDevice(zero)));

  Matrix subnormal = randomMatrix(5, 5, 15);
  subnormal(0, 1) = {1e-310, -1e-315};
  subnormal(2, 2) = {-4e-320, 2.2250738585072014e-308};
  Matrix expected = subnormal;
  Dense::flushSubnormals(expected);
  CudaMatrix flushed = toDevice(subnormal);
  Device::flushSubnormals(flushed);
  EXPECT_TRUE(sameBits(toHost(flushed), expected));

  const Matrix x = randomMatrix(11, 11, 16);
  Eigen::Matrix<Eigen::Index, Eigen::Dynamic, 1> indices(4);
  indices << 0, 120, 17, 64;
  Eigen::VectorXcd dense(4), device(4);
  Dense::sampleEntries(x, indices, dense);
  Device::sampleEntries(toDevice(x), indices, device);
  EXPECT_EQ(std::memcmp(dense.data(), device.data(), sizeof(dense(0)) * 4), 0);
}

// A matrix's record is the dense backend's, byte for byte, and loads back on either.
TEST(CudaBackend, RecordsAreTheDenseBackendsBytes) {
  SKIP_WITHOUT_GPU();
  const Matrix x = randomMatrix(9, 9, 17);
  BinaryRecordWriter dense_out, device_out;
  Dense::save(dense_out, x);
  Device::save(device_out, toDevice(x));
  EXPECT_EQ(dense_out.sealed(), device_out.sealed());
  BinaryRecordReader in = BinaryRecordReader::unseal(dense_out.sealed());
  CudaMatrix loaded = toDevice(Matrix::Zero(9, 9));
  Device::load(in, loaded);
  EXPECT_TRUE(sameBits(toHost(loaded), x));
  BinaryRecordReader again = BinaryRecordReader::unseal(dense_out.sealed());
  CudaMatrix other_size = toDevice(Matrix::Zero(8, 8));
  EXPECT_THROW(Device::load(again, other_size), CorruptRecord);
}

TEST(CudaBackend, LuSolvesAndReportsASingularMatrix) {
  SKIP_WITHOUT_GPU();
  for (const Eigen::Index n : {1, 6, 100}) {
    const Matrix a = randomMatrix(n, n, 18), b = randomMatrix(n, 3, 19);
    CudaMatrix factored = toDevice(a), solution = toDevice(b);
    Device::Lu lu;
    ASSERT_TRUE(lu.factor(factored));
    lu.solve(factored, solution);
    const Matrix x = toHost(solution);
    // Backward error: ‖a x − b‖ ≤ c·n·ε·‖a‖‖x‖.
    EXPECT_LE((a * x - b).norm(), 100 * double(n) * 1e-16 * a.norm() * x.norm()) << n;
  }
  // A zero column stays exactly zero through the elimination: a zero pivot, not a tiny one.
  Matrix singular = randomMatrix(5, 5, 20);
  singular.col(3).setZero();
  CudaMatrix factored = toDevice(singular);
  Device::Lu lu;
  EXPECT_FALSE(lu.factor(factored));
}

// The eigenbasis (cuSOLVER's zheevd, four zgemm and the weighing kernel) against the dense
// backend's: the phases, both phase functions and given weights (out may be in), the phases
// of another matrix on the eigenvectors, the result exactly skew-Hermitian; a non-finite x
// refused.
TEST(CudaBackend, EigenbasisAgreesWithTheDenseOne) {
  SKIP_WITHOUT_GPU();
  for (const Eigen::Index n : {1, 7, 64, 100}) {
    const Matrix r = randomMatrix(n, n, 21), s = randomMatrix(n, n, 22);
    const Matrix x = (r - r.adjoint()) / std::sqrt(double(n)), a = s - s.adjoint();
    Device::Eigenbasis basis;
    ASSERT_TRUE(basis.compute(toDevice(x))) << n;
    SkewHermitianEigenbasis<Matrix> dense;
    ASSERT_TRUE(dense.compute(x));
    EXPECT_LT((basis.phases() - dense.phases()).cwiseAbs().maxCoeff(),
              1e-13 * (1.0 + dense.phases().cwiseAbs().maxCoeff()))
        << n;
    EXPECT_NEAR(basis.adRadius(), dense.adRadius(), 1e-13 * (1.0 + dense.adRadius())) << n;
    for (const PhaseFunction f :
         {PhaseFunction::kCoadjointIncrement, PhaseFunction::kInverseDexpInverseDual}) {
      CudaMatrix inout = toDevice(a);
      basis.apply(f, 0.8, inout, inout);
      const Matrix result = toHost(inout);
      Matrix reference;
      dense.apply(f, 0.8, a, reference);
      EXPECT_LT((result - reference).norm(), 1e-13 * a.norm()) << n << ", " << int(f);
      EXPECT_TRUE(result == Matrix(-result.adjoint())) << n << ", " << int(f);
    }
    // The preconditioner's members: the phases of a on x's eigenvectors, and weights.
    Eigen::VectorXd pi, pi_reference;
    basis.diagonalPhasesOf(toDevice(a), pi);
    dense.diagonalPhasesOf(a, pi_reference);
    EXPECT_LT((pi - pi_reference).cwiseAbs().maxCoeff(), 1e-13 * a.norm()) << n;
    Eigen::MatrixXd weights(n, n);
    for (Eigen::Index b = 0; b < n; ++b) {
      for (Eigen::Index c = 0; c < n; ++c) weights(c, b) = 1.0 / (1.0 + std::abs(b - c));
    }
    basis.setWeights(weights);
    dense.setWeights(weights);
    CudaMatrix inout = toDevice(a);
    basis.applyWeights(inout, inout);
    const Matrix result = toHost(inout);
    Matrix reference;
    dense.applyWeights(a, reference);
    EXPECT_LT((result - reference).norm(), 1e-13 * a.norm()) << n << ", weights";
    EXPECT_TRUE(result == Matrix(-result.adjoint())) << n << ", weights";
  }
  Matrix x = randomMatrix(5, 5, 23);
  x = x - x.adjoint();
  x(2, 4) = NAN;
  Device::Eigenbasis basis;
  EXPECT_FALSE(basis.compute(toDevice(x)));
}

// The Poisson solve against HoppeYauLaplacian's on the host, and against Δ itself.
TEST(CudaPoissonSolver, AgreesWithTheHostSolve) {
  SKIP_WITHOUT_GPU();
  for (const Eigen::Index n : {2, 3, 16, 33, 128}) {
    const Matrix W = randomVorticity(n, 21) + Matrix::Identity(n, n) * std::complex<double>(0, 0.3);
    const HoppeYauLaplacian laplacian(n);
    Matrix expected;
    laplacian.solve(W, expected);
    CudaPoissonSolver solver(n);
    CudaMatrix out;
    solver.solve(toDevice(W), out);
    EXPECT_LE(relativeDifference(toHost(out), expected), 1e-13) << "N = " << n;
    // In place.
    CudaMatrix in_place = toDevice(W);
    solver.solve(in_place, in_place);
    EXPECT_LE(relativeDifference(toHost(in_place), expected), 1e-13) << "N = " << n;
  }
  CudaPoissonSolver solver(4);
  CudaMatrix wrong = toDevice(Matrix::Zero(5, 5)), out;
  EXPECT_THROW(solver.solve(wrong, out), InvalidArgument);
  EXPECT_THROW(CudaPoissonSolver(1), InvalidArgument);
}

// The magnetic fluid's current B = ΔΘ: the host apply's bits (the same operations in the same
// order, no fused multiply-add, a correctly rounded square root).
TEST(CudaPoissonSolver, AppliesTheLaplacianWithTheHostsBits) {
  SKIP_WITHOUT_GPU();
  for (const Eigen::Index n : {2, 3, 16, 33, 128}) {
    const Matrix Theta =
        randomVorticity(n, 23) + Matrix::Identity(n, n) * std::complex<double>(0.1, 0.3);
    Matrix expected(n, n);
    HoppeYauLaplacian(n).apply(Theta, expected);
    CudaPoissonSolver solver(n);
    CudaMatrix out;
    solver.apply(toDevice(Theta), out);
    EXPECT_TRUE(sameBits(toHost(out), expected))
        << "N = " << n << ", largest difference " << (toHost(out) - expected).cwiseAbs().maxCoeff();
  }
  CudaPoissonSolver solver(4);
  CudaMatrix theta = toDevice(Matrix::Zero(4, 4)), wrong = toDevice(Matrix::Zero(5, 5)), out;
  EXPECT_THROW(solver.apply(wrong, out), InvalidArgument);
  EXPECT_THROW(solver.apply(theta, theta), InvalidArgument);
}

// W0 with the real and imaginary part of every entry moved by one ulp, up or down at random
// (seeded), made skew-Hermitian again: a start that differs from W0 by rounding alone.
Matrix movedByOneUlp(const Matrix& W0) {
  std::mt19937_64 engine(5);
  std::uniform_int_distribution<int> coin(0, 1);
  const double e = std::numeric_limits<double>::epsilon();
  Matrix W = W0;
  for (Eigen::Index k = 0; k < W.size(); ++k) {
    W(k) = {W(k).real() * (1 + (coin(engine) ? e : -e)),
            W(k).imag() * (1 + (coin(engine) ? e : -e))};
  }
  return SUN::vee(W);
}

// W after 100 steps of a fixed h of `name` on `fluid` from W0.
template <class G>
typename G::template Dual<double> hundredSteps(
    const std::string& name, const std::shared_ptr<const LiePoissonSystem<G>>& fluid,
    const typename G::template Dual<double>& W0, double h) {
  RelaxOptions options;
  options.max_steps = 100;
  options.tolerance = 0.0;
  auto method = makeMethod<G>(name, fluid);
  Relaxation<G> run(*method, *fluid, W0, h, options);
  while (run.advance()) {
  }
  EXPECT_EQ(run.state().k, 100) << name << ": " << run.result().failure;
  return run.current();
}

// Every method for any backend, 100 steps of a fixed h on the fluid, on the GPU and on the
// dense backend from the same W0: the same trajectory to 1e-12 relative to W's largest entry, or,
// where the flow itself amplifies rounding beyond that, to 10 times what the dense run moves
// when its W0 moves by one ulp (the GPU's products and sums round otherwise at every step).
// Measured on the CPU (2026-11-29, docs/results/gpu.md): that motion is 4e-16 to 2e-15 for every
// method at alpha = 0 and for ddb-cay and rk4 at 0.5, but 1e-14 (sddb-cay) and 6.5e-14 (ddb4-cay,
// whose triple jump takes a backward substep) at N = 256, alpha = 0.5, growing with N.
TEST(CudaRelaxation, EveryMethodForAnyBackendFollowsTheDenseRun) {
  SKIP_WITHOUT_GPU();
  for (const Eigen::Index n : {16, 128, 512}) {
    for (const double alpha : {0.0, 0.5}) {
      const Matrix W0 = randomVorticity(n, 22), moved = movedByOneUlp(W0);
      const double h = zeitlinDefaultStep(W0, alpha);
      const auto dense_fluid = makeZeitlinFluid(n, alpha);
      const auto device_fluid = makeCudaZeitlinFluid(n, alpha);
      for (const std::string& name : methodNames(kBackendMatrixGroups)) {
        const std::string what =
            name + ", N = " + std::to_string(n) + ", alpha = " + std::to_string(alpha);
        const Matrix dense = hundredSteps<SUN>(name, dense_fluid, W0, h);
        const double rounding =
            relativeDifference(hundredSteps<SUN>(name, dense_fluid, moved, h), dense);
        const Matrix device = toHost(hundredSteps<CudaSUN>(name, device_fluid, toDevice(W0), h));
        EXPECT_LE(relativeDifference(device, dense), std::max(1e-12, 10 * rounding))
            << what << " (the dense run moves by " << rounding << " from W0 moved by one ulp)";
      }
    }
  }
}

// The Newton search on the GPU reaches the dense search's steady state. Its iterates follow the
// dense ones only for a few iterations, as on MPI ranks (docs/design/distributed.md, "The
// Newton search on the ranks"); at N = 16, α = −0.5 the search converges to one critical point:
// both stop at r ≤ 1e-10, within 1e-8 of each other.
TEST(CudaRelaxation, TheNewtonSearchReachesTheDenseSearchsSteadyState) {
  SKIP_WITHOUT_GPU();
  const Eigen::Index n = 16;
  const Matrix W0 = randomVorticity(n, 22);
  RelaxOptions options;
  options.newton = true;
  options.tolerance = 1e-10;
  options.max_steps = 400;
  const auto dense_fluid = makeZeitlinFluid(n, -0.5);
  const auto device_fluid = makeCudaZeitlinFluid(n, -0.5);
  Relaxation<SUN> dense(*dense_fluid, W0, options);
  while (dense.advance()) {
  }
  Relaxation<CudaSUN> device(*device_fluid, toDevice(W0), options);
  while (device.advance()) {
  }
  ASSERT_EQ(dense.result().stop, RelaxStop::kSteady) << dense.result().failure;
  EXPECT_EQ(device.result().stop, RelaxStop::kSteady) << device.result().failure;
  EXPECT_LE(relativeDifference(toHost(device.current()), dense.current()), 1e-8);
}

// Every method that runs on the dense magnetic fluid, 20 steps of h = 0.01 on the GPU and on the
// dense backend from the same (W0, Θ0), as on MPI ranks (tests/mpi/test_distributed_mhd.cc): the
// same states to 1e-12 of each part's largest entry, or to 10 times what the dense run moves from a
// start moved by one ulp where the flow amplifies rounding more (as for the fluid, above); the
// Casimirs tr Θᵏ and tr(WΘᵏ) of the GPU's state, computed on the host, to 1e-12 of their scales.
// The exponential rows too: the dual numbers' eigenbasis takes the CUDA eigenbasis in its
// coordinates, with the weights of core/eigenbasis_weights.h in the device's kernels.
static_assert(groupHasEigenbasis<CudaDualNumberSUN>() &&
              groupHasOrbitPreconditioner<CudaDualNumberSUN>());
TEST(CudaMhd, EveryMethodFollowsTheDenseRunAndKeepsTheCasimirs) {
  SKIP_WITHOUT_GPU();
  for (const Eigen::Index n : {16, 33}) {
    const double alpha = 0.5, h = 0.01;
    const Matrix W0 = randomVorticity(n, 1), Theta0 = 0.02 / double(n) * randomVorticity(n, 2);
    const DualMatrix<Matrix> mu0 = zeitlinMhdState(W0, Theta0),
                             moved = zeitlinMhdState(movedByOneUlp(W0), movedByOneUlp(Theta0));
    const auto dense_mhd = makeZeitlinMhd(n, alpha);
    const auto device_mhd = makeCudaZeitlinMhd(n, alpha);
    const auto twentySteps = [&](auto& method, auto mu) {
      for (int k = 0; k < 20; ++k) method.advance(mu, k * h, h);
      return mu;
    };
    for (const MethodInfo& m : kMethods) {
      if (!methodApplies(m, *dense_mhd)) continue;
      const std::string what = std::string(m.name) + ", N = " + std::to_string(n);
      ASSERT_TRUE(methodApplies(m, *device_mhd)) << what;
      // A method of its own for each run: a method keeps its last solves for its next guess.
      const DualMatrix<Matrix> dense = twentySteps(*makeMethod<DualNumberSUN>(m, dense_mhd), mu0);
      const DualMatrix<Matrix> dense_moved =
          twentySteps(*makeMethod<DualNumberSUN>(m, dense_mhd), moved);
      const auto device_method = makeMethod<CudaDualNumberSUN>(m, device_mhd);
      const DualMatrix<Matrix> device = toHost(twentySteps(*device_method, toDevice(mu0)));
      for (const auto& [part, name] :
           {std::pair{&DualMatrix<Matrix>::eps, "W"}, {&DualMatrix<Matrix>::real, "Theta"}}) {
        const double rounding = relativeDifference(dense_moved.*part, dense.*part);
        EXPECT_LE(relativeDifference(device.*part, dense.*part), std::max(1e-12, 10 * rounding))
            << what << ", " << name << " (the dense run moves by " << rounding << ")";
      }
      EXPECT_GT(relativeDifference(device.eps, W0), 1e-4) << what;
      if (m.keeps_casimirs) {
        EXPECT_LT(test::mhdCasimirDrift(mu0, device), 1e-12) << what;
      }
    }
  }
}

// On one device a run repeats to the bit (the reductions add in a fixed tree; cuBLAS and
// cuSOLVER in their default modes are deterministic): what a resumed run relies on.
TEST(CudaRelaxation, ARunRepeatsToTheBit) {
  SKIP_WITHOUT_GPU();
  const Eigen::Index n = 96;
  const Matrix W0 = randomVorticity(n, 25);
  const auto fluid = makeCudaZeitlinFluid(n, 0.5);
  const auto once = [&] {
    auto method = makeMethod<CudaSUN>("sddb-cay", fluid);
    RelaxOptions options;
    options.max_steps = 30;
    options.tolerance = 0.0;
    Relaxation<CudaSUN> run(*method, *fluid, toDevice(W0), zeitlinDefaultStep(W0, 0.5), options);
    while (run.advance()) {
    }
    return toHost(run.current());
  };
  const Matrix first = once(), second = once();
  EXPECT_TRUE(sameBits(first, second));
}

// Contexts (cuda/cuda_context.h): made on a device or refused with the runtime's reason.
TEST(CudaContext, IsMadeOnADeviceOrSaysWhyNot) {
  if (const auto why = cudaUnavailable()) {
    EXPECT_THAT([] { CudaContext::create(); }, ::testing::ThrowsMessage<CudaError>(*why));
    return;
  }
  const auto a = CudaContext::create(), b = CudaContext::create();
  EXPECT_NE(a, b);
  EXPECT_EQ(CudaContext::ofThisThread(), CudaContext::ofThisThread());
  EXPECT_EQ(toDevice(randomMatrix(3, 3, 1), a).context(), a);
  EXPECT_EQ(toDevice(randomMatrix(3, 3, 1)).context(), CudaContext::ofThisThread());
  a->synchronize();
}

// Each context's stream orders its own run: the same run in two contexts of their own and in
// this thread's takes the same bits, and what a run makes stays in its context.
TEST(CudaContext, RunsInTwoContextsTakeTheSameBits) {
  SKIP_WITHOUT_GPU();
  const Eigen::Index n = 48;
  const Matrix W0 = randomVorticity(n, 26);
  const auto runIn = [&](const std::shared_ptr<CudaContext>& context) {
    const auto fluid = makeCudaZeitlinFluid(n, 0.5, context);
    auto method = makeMethod<CudaSUN>("sddb-cay", fluid);
    RelaxOptions options;
    options.max_steps = 20;
    options.tolerance = 0.0;
    const CudaMatrix start = context ? toDevice(W0, context) : toDevice(W0);
    Relaxation<CudaSUN> run(*method, *fluid, start, zeitlinDefaultStep(W0, 0.5), options);
    while (run.advance()) {
    }
    EXPECT_EQ(run.current().context(), context ? context : CudaContext::ofThisThread());
    return toHost(run.current());
  };
  const Matrix own = runIn(nullptr);
  EXPECT_TRUE(sameBits(runIn(CudaContext::create()), own));
  EXPECT_TRUE(sameBits(runIn(CudaContext::create()), own));
}

// The operands of one operation share a context: two contexts' streams are not ordered with
// each other, so a mix is refused by name, where it would read entries still being written.
TEST(CudaContext, OperandsOfTwoContextsAreRefused) {
  SKIP_WITHOUT_GPU();
  const Matrix m = randomMatrix(8, 8, 2);
  const auto a = CudaContext::create(), b = CudaContext::create();
  const CudaMatrix x = toDevice(m, a);
  CudaMatrix y = toDevice(m, b), out;
  const auto refused =
      ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("CudaContext"));
  EXPECT_THAT([&] { Device::axpy(1.0, x, y); }, refused);
  EXPECT_THAT([&] { Device::innerProduct(x, y); }, refused);
  EXPECT_THAT([&] { Device::multiply(x, y, out); }, refused);
  CudaPoissonSolver poisson(8, 0.0, a);
  EXPECT_THAT([&] { poisson.solve(y, out); }, refused);
  // LU keeps its pivots in the context it factored in: a solve in another is refused.
  CudaLu lu;
  CudaMatrix factored = toDevice(Matrix(m + 8.0 * Matrix::Identity(8, 8)), a);
  ASSERT_TRUE(lu.factor(factored));
  EXPECT_THAT([&] { lu.solve(factored, y); }, refused);
  // An output takes its input's context.
  Device::scale(2.0, x, y);
  EXPECT_EQ(y.context(), a);
  EXPECT_TRUE(sameBits(toHost(y), Matrix(2.0 * m)));
}

// A matrix keeps its context alive: one made in a thread that has ended is still read, its
// context's stream and scratch with it (nothing of the backend is the thread's).
TEST(CudaContext, AMatrixOutlivesTheThreadThatMadeIt) {
  SKIP_WITHOUT_GPU();
  const Matrix m = randomMatrix(64, 64, 3);
  CudaMatrix x;
  std::thread([&] { x = toDevice(m); }).join();
  EXPECT_NE(x.context(), CudaContext::ofThisThread());
  EXPECT_TRUE(sameBits(toHost(x), m));
  EXPECT_NEAR(Device::frobeniusNorm(x), m.norm(), 1e-12 * m.norm());
}

// The Casimirs on the device: 1000 steps at N = 1024 keep W's spectrum to 1e-13.
TEST(CudaRelaxation, KeepsTheSpectrumOverAThousandStepsAtN1024) {
  SKIP_WITHOUT_GPU();
  const Eigen::Index n = 1024;
  const double alpha = 0.5;
  const Matrix W0 = randomVorticity(n, 23);
  const auto fluid = makeCudaZeitlinFluid(n, alpha);
  auto method = makeMethod<CudaSUN>("ddb-cay", fluid);
  RelaxOptions options;
  options.max_steps = 1000;
  options.tolerance = 0.0;
  Relaxation<CudaSUN> run(*method, *fluid, toDevice(W0), zeitlinDefaultStep(W0, alpha), options);
  const double initial_energy = run.state().energy;
  while (run.advance()) {
  }
  ASSERT_EQ(run.state().k, 1000) << run.result().failure;
  const Eigen::VectorXd before = SUN::casimirs(W0), after = SUN::casimirs(toHost(run.current()));
  EXPECT_LE((after - before).norm() / before.norm(), 1e-13);
  EXPECT_LT(run.state().energy, initial_energy);
}

// A relaxation saved on one device resumes on the other: the GPU's record loads into a CPU
// relaxation and the CPU's into a GPU one, and both follow the uninterrupted run to 1e-12.
TEST(CudaRelaxation, ACheckpointMovesBetweenTheCpuAndTheGpu) {
  SKIP_WITHOUT_GPU();
  const Eigen::Index n = 48;
  const double alpha = 0.5;
  const Matrix W0 = randomVorticity(n, 24);
  const double h = zeitlinDefaultStep(W0, alpha);
  const auto dense_fluid = makeZeitlinFluid(n, alpha);
  const auto device_fluid = makeCudaZeitlinFluid(n, alpha);
  RelaxOptions options;
  options.max_steps = 40;
  options.tolerance = 0.0;
  auto whole_method = makeMethod<SUN>("sddb-cay", dense_fluid);
  Relaxation<SUN> whole(*whole_method, *dense_fluid, W0, h, options);
  while (whole.advance()) {
  }
  const auto halfway = [&](auto& run) {
    for (int k = 0; k < 20; ++k) ASSERT_TRUE(run.advance());
  };
  // GPU → CPU.
  {
    auto first_method = makeMethod<CudaSUN>("sddb-cay", device_fluid);
    Relaxation<CudaSUN> first(*first_method, *device_fluid, toDevice(W0), h, options);
    halfway(first);
    BinaryRecordWriter out;
    first.save(out);
    BinaryRecordReader in = BinaryRecordReader::unseal(out.sealed());
    auto second_method = makeMethod<SUN>("sddb-cay", dense_fluid);
    Relaxation<SUN> second(*second_method, *dense_fluid, W0, h, options);
    second.load(in);
    EXPECT_TRUE(in.atEnd());
    while (second.advance()) {
    }
    EXPECT_EQ(second.state().k, 40);
    EXPECT_LE(relativeDifference(second.current(), whole.current()), 1e-12);
  }
  // CPU → GPU.
  {
    auto first_method = makeMethod<SUN>("sddb-cay", dense_fluid);
    Relaxation<SUN> first(*first_method, *dense_fluid, W0, h, options);
    halfway(first);
    BinaryRecordWriter out;
    first.save(out);
    BinaryRecordReader in = BinaryRecordReader::unseal(out.sealed());
    auto second_method = makeMethod<CudaSUN>("sddb-cay", device_fluid);
    Relaxation<CudaSUN> second(*second_method, *device_fluid, toDevice(W0), h, options);
    second.load(in);
    EXPECT_TRUE(in.atEnd());
    while (second.advance()) {
    }
    EXPECT_EQ(second.state().k, 40);
    EXPECT_LE(relativeDifference(toHost(second.current()), whole.current()), 1e-12);
  }
}

// Damping and forcing on the GPU (cudaZeitlinExactFlows: the host's flows on a copy of the
// state): ddb-cay Strang-split with viscosity, drag, a stochastic band and a fixed forcing on a
// rotating sphere, both viscous schemes, follows the dense run to 1e-12 over 40 steps; the run
// saved on the GPU after 20 steps (the forcing's kick count in its record) and resumed on the CPU
// lands on the uninterrupted run's state to 1e-12.
TEST(CudaRelaxation, DampedAndForcedRunsFollowTheDenseRunAndMoveToTheCpu) {
  SKIP_WITHOUT_GPU();
  const Eigen::Index n = 48;
  const double alpha = 0.5;
  ZeitlinPhysics physics;
  physics.rotation = 1.5;
  const Matrix F = zeitlinPlanetaryVorticity(n, physics.rotation);
  const Matrix Q0 = randomVorticity(n, 26) + F;
  const double h = 0.5 * zeitlinDefaultStep(Q0, alpha);
  const auto dense_fluid = makeZeitlinFluid(n, alpha, physics);
  const auto device_fluid = makeCudaZeitlinFluid(n, alpha, physics);
  const auto& hamiltonian = dynamic_cast<const ZeitlinHamiltonian&>(dense_fluid->hamiltonian());
  for (const auto scheme : {ZeitlinViscousScheme::kExact, ZeitlinViscousScheme::kImplicit}) {
    ZeitlinDampingAndForcing d;
    d.viscosity = {1e-3, 2, 0.05, scheme};
    d.forcing = {6, 2, 1e-3, 7};
    d.fixed_forcing = 1e-2 * randomVorticity(n, 27);
    const auto split = [&](auto method, auto flows) {
      for (auto& flow : flows) {
        using G = typename decltype(method)::element_type::Group;
        method = std::make_unique<StrangSplitting<G>>(std::move(method), std::move(flow));
      }
      return method;
    };
    const auto dense_method = [&] {
      return split(makeMethod<SUN>("ddb-cay", dense_fluid), zeitlinExactFlows(hamiltonian, d));
    };
    const auto device_method = [&] {
      return split(makeMethod<CudaSUN>("ddb-cay", device_fluid),
                   cudaZeitlinExactFlows(hamiltonian, d));
    };
    RelaxOptions options;
    options.max_steps = 40;
    options.tolerance = 0.0;
    auto whole_method = dense_method();
    Relaxation<SUN> whole(*whole_method, *dense_fluid, Q0, h, options);
    while (whole.advance()) {
    }
    ASSERT_EQ(whole.state().k, 40) << whole.result().failure;
    auto device_whole_method = device_method();
    Relaxation<CudaSUN> device(*device_whole_method, *device_fluid, toDevice(Q0), h, options);
    while (device.advance()) {
    }
    EXPECT_LE(relativeDifference(toHost(device.current()), whole.current()), 1e-12);
    auto first_method = device_method();
    Relaxation<CudaSUN> first(*first_method, *device_fluid, toDevice(Q0), h, options);
    for (int k = 0; k < 20; ++k) ASSERT_TRUE(first.advance());
    BinaryRecordWriter out;
    first.save(out);
    BinaryRecordReader in = BinaryRecordReader::unseal(out.sealed());
    auto second_method = dense_method();
    Relaxation<SUN> second(*second_method, *dense_fluid, Q0, h, options);
    second.load(in);
    EXPECT_TRUE(in.atEnd());
    while (second.advance()) {
    }
    EXPECT_EQ(second.state().k, 40);
    EXPECT_LE(relativeDifference(second.current(), whole.current()), 1e-12);
  }
}

}  // namespace
}  // namespace ddb
