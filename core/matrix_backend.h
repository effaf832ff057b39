// MatrixBackend<X>: all the arithmetic of the matrix groups' step formulas, so that one
// formula serves a dense matrix, a matrix distributed over MPI ranks and any other storage
// (docs/design/matrix-backend.md is the contract a backend implements). As in Boost.Odeint's
// algebra and operations, a formula never touches entries: it combines matrices by the
// element-wise operations below (copy, setZero, scale, divide, axpy, sum, addSum,
// addCombination) and couples them by the functions after them: products, adjoints,
// traces, norms, sampled entries and LU solves. Every reduction returns the same value on
// every rank, so that every data-dependent branch is taken alike everywhere.
//
// This primary template is the dense backend (Eigen's dynamic-size matrices, real or
// complex); core/fixed_size_backend.h specialises it for the small groups' fixed-size vectors
// (the second parameter selects that specialisation), distributed/distributed_backend.h for
// DistributedMatrix.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/detail/blas_threads.h>
#include <ddb/core/detail/dense_lu.h>
#include <ddb/core/errors.h>
#include <ddb/core/matrix_traits.h>
#include <ddb/core/parallel_passes.h>
#include <ddb/core/thread_pool.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

namespace ddb {

template <class Matrix>
class SkewHermitianEigenbasis;  // core/skew_hermitian_eigenbasis.h

template <class X, class = void>
struct MatrixBackend {
  using Scalar = typename X::Scalar;
  using Entries = X;
  /// LU factors of A in place and solves X ← A⁻¹X, workspaces reused (factor(A) returns
  /// false when A is singular).
  using Lu = DenseLu<X>;
  /// The spectral calculus of a skew-Hermitian x, x = V diag(iθ) Vᴴ: compute(x) (false when
  /// x is not finite), adRadius() = θ_max − θ_min, and apply(f, scale, in, out),
  /// out = V [F ∘ (Vᴴ in V)] Vᴴ with F_ab = f(scale (θ_a − θ_b)) for the functions of
  /// core/phase_function.h. Defined in core/skew_hermitian_eigenbasis.h, which its users
  /// include.
  using Eigenbasis = SkewHermitianEigenbasis<X>;
  /// Eigenbasis works in its own coordinates too (toBasis, fromBasis, weigh), on which the
  /// dual numbers' eigenbasis is built (core/dual_eigenbasis.h).
  static constexpr bool kEigenbasisCoordinates = true;

  // ---- Element-wise operations. Each entry of the result is its own expression of the
  // operands' entries at the same place, computed as written (left to right, no fused
  // multiply-add), so the bits do not depend on the backend's threads or storage. `out`
  // may be one of the operands. Coefficients ±1 are taken as additions and subtractions:
  // 1·x = x and (−1)·x = −x exactly, so that is the same result, vectorised. ----

  /// out ← x (out takes x's shape).
  static void copy(const X& x, X& out) { assignInParallel(out, x); }
  /// x ← 0, keeping x's shape.
  static void setZero(X& x) {
    ThreadPool::instance().forColumnRanges(
        x.rows(), x.cols(), [&](long first, long count) { x.middleCols(first, count).setZero(); });
  }
  /// out ← a·x.
  static void scale(double a, const X& x, X& out) {
    withTerm(a, x, [&](const auto& ax) { assignInParallel(out, ax); });
  }
  /// x ← x / a, real and imaginary parts divided by a (not scale(1/a, x), which rounds twice;
  /// nor Eigen's x /= a, which on a complex x divides by the complex a + 0i, libgcc's
  /// complex division, whose rounding differs in about half the entries).
  static void divide(X& x, double a) { assignInParallel(x, x / a); }
  /// y ← y + a·x.
  static void axpy(double a, const X& x, X& y) {
    withTerm(a, x, [&](const auto& ax) { addInParallel(y, ax); });
  }
  /// out ← a·x + b·y.
  static void sum(double a, const X& x, double b, const X& y, X& out) {
    withTerm(a, x, [&](const auto& ax) {
      withTerm(b, y, [&](const auto& by) { assignInParallel(out, ax + by); });
    });
  }
  /// out ← (a·x + b·y) + c·z.
  static void sum(double a, const X& x, double b, const X& y, double c, const X& z, X& out) {
    withTerm(a, x, [&](const auto& ax) {
      withTerm(b, y, [&](const auto& by) {
        withTerm(c, z, [&](const auto& cz) { assignInParallel(out, ax + by + cz); });
      });
    });
  }
  /// out ← out + (a·x + b·y).
  static void addSum(double a, const X& x, double b, const X& y, X& out) {
    withTerm(a, x, [&](const auto& ax) {
      withTerm(b, y, [&](const auto& by) { addInParallel(out, ax + by); });
    });
  }
  /// out ← (((out + c₀·term(0)) + c₁·term(1)) + …) for j < count, term(j) a const X&. Block
  /// of columns by block, so that each block of out stays in cache while the terms are added
  /// (one pass over out instead of count); column ranges on the library's threads.
  template <class Coefficients, class Term>
  static void addCombination(const Coefficients& c, const Term& term, int count, X& out) {
    constexpr Eigen::Index kBlockColumns = 16;
    ThreadPool::instance().forColumnRanges(
        out.rows(), out.cols(), [&](Eigen::Index begin, Eigen::Index width) {
          for (Eigen::Index first = begin; first < begin + width; first += kBlockColumns) {
            const Eigen::Index cols = std::min(kBlockColumns, begin + width - first);
            auto block = out.middleCols(first, cols);
            for (int j = 0; j < count; ++j) block += c(j) * term(j).middleCols(first, cols);
          }
        });
  }

  /// x's entries as an error message shows them (errors.h, formatValue).
  static FormattedValue describe(const X& x) { return {formatValue(x)}; }

  /// Whether x has like's shape (and, distributed, layout).
  static bool sameShape(const X& x, const X& like) {
    return x.rows() == like.rows() && x.cols() == like.cols();
  }
  /// x ← zero of like's shape.
  static void zeroLike(X& x, const X& like) { x.setZero(like.rows(), like.cols()); }
  /// The number of rows of the whole matrix.
  static Eigen::Index rows(const X& x) { return x.rows(); }
  /// The number of entries of the whole matrix.
  static Eigen::Index globalSize(const X& x) { return x.size(); }

  /// out = a b (out aliases neither). Under a single-threaded BLAS, by chunks of columns of
  /// out, one BLAS call each, on the library's threads (core/detail/blas_threads.h).
  static void multiply(const X& a, const X& b, X& out) {
    out.resize(a.rows(), b.cols());
    detail::forBlasColumnChunks(b.cols(), [&](long first, long count) {
      out.middleCols(first, count).noalias() = a * b.middleCols(first, count);
    });
  }
  /// out += a·x y (out aliases neither): one product accumulated into out, Eigen's
  /// out.noalias() += a·x·y (one GEMM with β = 1; a = ±1 as +=, −=).
  static void multiplyAdd(double a, const X& x, const X& y, X& out) {
    if (a == 1.0) {
      out.noalias() += x * y;
    } else if (a == -1.0) {
      out.noalias() -= x * y;
    } else {
      out.noalias() += Scalar(a) * x * y;
    }
  }
  /// out += scale·xᴴ (out is not x). Tile by tile, each tile of x read by columns into a
  /// small buffer first (loadTransposed below), tile columns on the library's threads
  /// (core/thread_pool.h).
  static void addAdjoint(double scale, const X& x, X& out) {
    const Eigen::Index n = out.rows(), m = out.cols(), tiles = (m + kTile - 1) / kTile;
    ThreadPool& pool = ThreadPool::instance();
    const int tasks = static_cast<int>(std::min<long>(pool.tasksFor(n * m), tiles));
    pool.run(tasks, [&](int task) {
      Tile buffer;
      const Eigen::Index first = tiles * task / tasks, end = tiles * (task + 1) / tasks;
      for (Eigen::Index j0 = first * kTile; j0 < std::min(m, end * kTile); j0 += kTile) {
        const Eigen::Index cols = std::min(kTile, m - j0);
        for (Eigen::Index i0 = 0; i0 < n; i0 += kTile) {
          const Eigen::Index rows = std::min(kTile, n - i0);
          loadTransposed(x, j0, i0, cols, rows, buffer);  // buffer(a, b) = x(j0 + b, i0 + a)
          for (Eigen::Index b = 0; b < cols; ++b) {
            for (Eigen::Index a = 0; a < rows; ++a) {
              out(i0 + a, j0 + b) += scale * Eigen::numext::conj(buffer(a, b));
            }
          }
        }
      }
    });
  }
  /// x ← (x − xᴴ)/2 in place, skew-Hermitian bit for bit: entry (j, i) is −conj(entry (i, j)),
  /// the diagonal imaginary (zero for real x). Tile pairs (I, J), (J, I) of the upper
  /// triangle's tiles, the lower one through a buffer; tile columns on the library's threads
  /// in shares of equal work.
  static void makeSkewHermitian(X& x) {
    const Eigen::Index n = x.cols(), tiles = (n + kTile - 1) / kTile;
    ThreadPool& pool = ThreadPool::instance();
    const int tasks = static_cast<int>(std::min<long>(pool.tasksFor(n * n / 2), tiles));
    pool.run(tasks, [&](int task) {
      // Tile column J holds J + 1 tiles of the triangle: the first J of task k is about
      // tiles·√(k/tasks).
      const auto split = [&](int k) {
        return static_cast<Eigen::Index>(std::lround(double(tiles) * std::sqrt(double(k) / tasks)));
      };
      Tile buffer;
      for (Eigen::Index tj = split(task); tj < split(task + 1); ++tj) {
        const Eigen::Index j0 = tj * kTile, cols = std::min(kTile, n - j0);
        for (Eigen::Index i0 = 0; i0 < j0; i0 += kTile) {
          loadTransposed(x, j0, i0, cols, kTile, buffer);  // buffer(a, b) = x(j0 + b, i0 + a)
          for (Eigen::Index b = 0; b < cols; ++b) {
            for (Eigen::Index a = 0; a < kTile; ++a) {
              const Scalar v = skewPart(x(i0 + a, j0 + b), buffer(a, b));
              x(i0 + a, j0 + b) = v;
              buffer(a, b) = -Eigen::numext::conj(v);
            }
          }
          for (Eigen::Index a = 0; a < kTile; ++a) {
            for (Eigen::Index b = 0; b < cols; ++b) x(j0 + b, i0 + a) = buffer(a, b);
          }
        }
        // The diagonal tile, in place.
        for (Eigen::Index j = j0; j < j0 + cols; ++j) {
          for (Eigen::Index i = j0; i < j; ++i) {
            const Scalar v = skewPart(x(i, j), x(j, i));
            x(i, j) = v;
            x(j, i) = -Eigen::numext::conj(v);
          }
          x(j, j) = skewPart(x(j, j), x(j, j));
        }
      }
    });
  }
  /// Entry (i, j) of (x − xᴴ)/2 from x_ij and x_ji.
  static Scalar skewPart(const Scalar& upper, const Scalar& lower) {
    return 0.5 * (upper - Eigen::numext::conj(lower));
  }
  static Scalar trace(const X& x) { return x.trace(); }
  /// x ← x + c·I.
  static void addToDiagonal(X& x, Scalar c) { x.diagonal().array() += c; }

  static double frobeniusNorm(const X& x) { return x.norm(); }
  /// ‖x − y‖_F.
  static double frobeniusDistance(const X& x, const X& y) { return (x - y).norm(); }
  /// ‖x‖₁, the largest column sum of |x_ij| (an upper bound of ‖x‖₂ for normal x). |z| is
  /// √(Re² + Im²), vectorised: std::abs of a complex calls hypot, which made this norm a
  /// visible share of a fluid step (docs/design/architecture.md, "Threads"). Where |z|² may have
  /// under- or overflowed (a norm that is tiny or not finite) hypot's exact |z| is used. NaN
  /// entries make it NaN.
  /// Column ranges on the library's threads: the largest sum does not depend on them.
  static double oneNorm(const X& x) {
    const double fast =
        largestColumnSum(x, [](const auto& block) { return fastMagnitudes(block); });
    if (squaresWereExact(fast)) return fast;
    return largestColumnSum(x, [](const auto& block) { return block.cwiseAbs(); });
  }
  /// |x_ij| = √(Re² + Im²) entry by entry (an expression on an Eigen matrix: the distributed
  /// backend's local blocks too).
  template <class Entries>
  static auto fastMagnitudes(const Entries& x) {
    return x.cwiseAbs2().cwiseSqrt();
  }
  /// Whether a norm from the squares can be trusted: entries lost below √(smallest double)
  /// are below rounding relative to a norm of at least kSquaresExact, and nothing overflowed.
  static bool squaresWereExact(double norm) {
    constexpr double kSquaresExact = 1e-100;
    return norm >= kSquaresExact && norm <= std::numeric_limits<double>::max();
  }
  /// Re tr(xᴴy), the real inner product: Σ Re x̄_ij y_ij = Σ (Re x Re y + Im x Im y), the
  /// dot product of the entries' real and imaginary parts as one real vector (vectorised;
  /// nothing computes the imaginary part that the trace drops).
  static double innerProduct(const X& x, const X& y) {
    using Real = typename Eigen::NumTraits<Scalar>::Real;
    using Parts = Eigen::Map<const Eigen::Matrix<Real, Eigen::Dynamic, 1>>;
    constexpr Eigen::Index kParts = Eigen::NumTraits<Scalar>::IsComplex ? 2 : 1;
    // std::complex<Real> is laid out as Real[2] (C++17 [complex.numbers]/4).
    return Parts(reinterpret_cast<const Real*>(x.data()), x.size() * kParts)
        .dot(Parts(reinterpret_cast<const Real*>(y.data()), y.size() * kParts));
  }
  /// Whether every entry is finite (no NaN, no infinity).
  static bool allFinite(const X& x) { return x.allFinite(); }
  /// Sets the subnormal entries (real and imaginary parts alike), 0 < |x| < 2^-1022, to zero of
  /// the same sign and changes no other bit (OneStepMethod's integrate(): a decaying entry that
  /// reaches the subnormal range would make every later step pay the CPU's slow path on it).
  static void flushSubnormals(X& x) {
    using Real = typename Eigen::NumTraits<Scalar>::Real;
    constexpr Eigen::Index kParts = Eigen::NumTraits<Scalar>::IsComplex ? 2 : 1;
    // std::complex<Real> is laid out as Real[2] (C++17 [complex.numbers]/4).
    Real* entries = reinterpret_cast<Real*>(x.data());
    for (Eigen::Index i = 0; i < kParts * x.size(); ++i) {
      if (std::fpclassify(entries[i]) == FP_SUBNORMAL) {
        entries[i] = std::copysign(Real(0), entries[i]);
      }
    }
  }
  /// Whether every entry is exactly zero (NaN is not).
  static bool isZero(const X& x) {
    std::atomic<bool> nonzero{false};
    ThreadPool::instance().forColumnRanges(x.rows(), x.cols(), [&](long first, long count) {
      // Exactly zero: Eigen's isZero(0) compares |z|², which rounds to 0 for tiny z.
      if ((x.middleCols(first, count).array() != Scalar(0)).any()) {
        nonzero.store(true, std::memory_order_relaxed);
      }
    });
    return !nonzero.load(std::memory_order_relaxed);
  }

  /// out(s) = x(indices(s)) with column-major linear indices into the whole matrix.
  template <class Indices, class Out>
  static void sampleEntries(const X& x, const Indices& indices, Out& out) {
    for (Eigen::Index s = 0; s < indices.size(); ++s) out(s) = x(indices(s));
  }

  /// x, whole, into a record (a warm start: OneStepMethod::saveWarmStart).
  static void save(BinaryRecordWriter& out, const X& x) { out.put(x); }
  /// x ← the matrix a record holds, of x's shape (else CorruptRecord).
  static void load(BinaryRecordReader& in, X& x) {
    X read;
    in.get(read);
    if (!sameShape(read, x)) throw CorruptRecord("a matrix of another size than the state");
    x = std::move(read);
  }

 private:
  // f(a·x) with a·x as the expression x, −x or a·x: ±1 exactly as additions (vectorised).
  template <class F>
  static void withTerm(double a, const X& x, F&& f) {
    if (a == 1.0) {
      f(x);
    } else if (a == -1.0) {
      f(-x);
    } else {
      f(a * x);
    }
  }

  // The transposing passes go tile by tile and read the transposed tile by its columns:
  // reading it along its rows strides by a column's length, which for N a multiple of 256
  // (complex) maps every access to the same cache set (docs/design/architecture.md, "Threads").
  static constexpr Eigen::Index kTile = 32;
  using Tile = Eigen::Matrix<Scalar, kTile, kTile>;

  // The largest column sum of magnitudes(block) over the columns of x, NaN if any is NaN.
  template <class Magnitudes>
  static double largestColumnSum(const X& x, const Magnitudes& magnitudes) {
    if (x.cols() == 0) return 0.0;
    ThreadPool& pool = ThreadPool::instance();
    std::array<double, ThreadPool::kMaxTasks> largest;
    const int tasks = static_cast<int>(std::min<long>(pool.tasksFor(x.size()), x.cols()));
    pool.run(tasks, [&](int task) {
      const Eigen::Index first = x.cols() * task / tasks, end = x.cols() * (task + 1) / tasks;
      largest[static_cast<std::size_t>(task)] = magnitudes(x.middleCols(first, end - first))
                                                    .colwise()
                                                    .sum()
                                                    .template maxCoeff<Eigen::PropagateNaN>();
    });
    double result = largest[0];
    for (int task = 1; task < tasks; ++task) {
      const double value = largest[static_cast<std::size_t>(task)];
      if (std::isnan(value) || value > result) result = value;
    }
    return result;
  }

  // buffer(a, b) = x(row + b, col + a) for b < rows, a < cols: the block of x at (row, col),
  // transposed, read column by column.
  static void loadTransposed(const X& x, Eigen::Index row, Eigen::Index col, Eigen::Index rows,
                             Eigen::Index cols, Tile& buffer) {
    for (Eigen::Index a = 0; a < cols; ++a) {
      for (Eigen::Index b = 0; b < rows; ++b) buffer(a, b) = x(row + b, col + a);
    }
  }
};

/// Whether X's backend has the spectral calculus `Eigenbasis`, which the exponential methods need
/// (method_table.h; a backend may go without it: core/dual_matrix.h).
template <class X, class = void>
struct HasEigenbasis : std::false_type {};
template <class X>
struct HasEigenbasis<X, std::void_t<typename MatrixBackend<X>::Eigenbasis>> : std::true_type {};

/// Whether X's states have the Newton search's preconditioner on the orbit
/// (integrators/solvers/orbit_preconditioner.h), which the linearly implicit methods and the
/// search need: where X has an Eigenbasis (its entries' weights where it weighs them), and on
/// dual-number matrices of any part (the shift's, core/dual_matrix.h).
template <class X, class = void>
struct HasOrbitPreconditioner : HasEigenbasis<X> {};

/// requireFinite (errors.h) for a state of any backend: InvalidArgument naming `name` unless
/// every entry of x is finite.
template <class X>
const X& requireFiniteMatrix(const std::string& name, const X& x) {
  if constexpr (isEigenMatrix<X>) {
    return requireFinite(name, x);
  } else {
    using B = MatrixBackend<X>;
    if (!B::allFinite(x)) throwInvalid(name, B::describe(x).text, "every entry must be finite");
    return x;
  }
}

}  // namespace ddb

#include <ddb/core/fixed_size_backend.h>
