// MatrixBackend<DistributedMatrix>: the matrix backend (core/matrix_backend.h) of a
// block-cyclic matrix, so that the matrix groups' step formulas run unchanged on matrices
// distributed over MPI ranks (docs/design/distributed.md, "One step formula"). The operands of one
// formula share a layout, so the element-wise operations are the dense backend's on this
// rank's local arrays. Products are pzgemm_,
// adjoints an AdjointExchange, the 1-norm from column sums as the dense backend's, LU factors and
// solves pzgetrf_ + pzgetrs_, the exponential's eigenbasis pzheevd_ (distributed_eigenbasis.h);
// sums over the ranks are ProcessGrid::sum (the same bits on every
// rank). All functions are collective.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/errors.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/distributed/adjoint_exchange.h>
#include <ddb/distributed/distributed_eigenbasis.h>
#include <ddb/distributed/distributed_lu.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/distributed_product.h>
#include <ddb/distributed/rank_zero_record_reader.h>
#include <ddb/distributed/scalapack.h>
#include <mpi.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

namespace ddb {

template <>
struct MatrixBackend<DistributedMatrix> {
  using X = DistributedMatrix;
  using Scalar = std::complex<double>;
  using Entries = Eigen::MatrixXcd;
  using Lu = DistributedLu;
  using Eigenbasis = DistributedEigenbasis;
  /// DistributedEigenbasis works in its own coordinates too (core/matrix_backend.h).
  static constexpr bool kEigenbasisCoordinates = true;
  using Dense = MatrixBackend<Entries>;

  // The element-wise operations (core/matrix_backend.h) on the local arrays.
  static void copy(const X& x, X& out) {
    if (!out.sameLayout(x)) out = DistributedMatrix(x.layout());
    Dense::copy(x.local(), out.local());
  }
  static void setZero(X& x) { Dense::setZero(x.local()); }
  static void scale(double a, const X& x, X& out) { Dense::scale(a, x.local(), out.local()); }
  static void divide(X& x, double a) { Dense::divide(x.local(), a); }
  static void axpy(double a, const X& x, X& y) { Dense::axpy(a, x.local(), y.local()); }
  static void sum(double a, const X& x, double b, const X& y, X& out) {
    Dense::sum(a, x.local(), b, y.local(), out.local());
  }
  static void sum(double a, const X& x, double b, const X& y, double c, const X& z, X& out) {
    Dense::sum(a, x.local(), b, y.local(), c, z.local(), out.local());
  }
  static void addSum(double a, const X& x, double b, const X& y, X& out) {
    Dense::addSum(a, x.local(), b, y.local(), out.local());
  }
  template <class Coefficients, class Term>
  static void addCombination(const Coefficients& c, const Term& term, int count, X& out) {
    Dense::addCombination(
        c, [&](int j) -> const Entries& { return term(j).local(); }, count, out.local());
  }
  /// This rank's entries, for an error message.
  /// Named by what every rank agrees on (collective), not by a rank's own block of entries.
  static FormattedValue describe(const X& x) {
    return {"a " + std::to_string(x.size()) + "x" + std::to_string(x.size()) +
            " distributed matrix whose Frobenius norm is " + formatValue(frobeniusNorm(x))};
  }

  static bool sameShape(const X& x, const X& like) { return x.sameLayout(like); }
  static void zeroLike(X& x, const X& like) { x = DistributedMatrix(like.layout()); }
  static Eigen::Index rows(const X& x) { return x.size(); }
  static Eigen::Index globalSize(const X& x) { return Eigen::Index(x.size()) * x.size(); }

  static void multiply(const X& a, const X& b, X& out) { ddb::multiply(a, b, out); }
  static void multiplyAdd(double s, const X& a, const X& b, X& out) {
    multiplyInto(s, a, b, 1.0, out);
  }
  static void addAdjoint(double scale, const X& x, X& out) {
    adjointExchange(x.layout()).addAdjoint(scale, x.local(), out.local());
  }
  /// x ← (x − xᴴ)/2 entry by entry as the dense backend forms it, so skew-Hermitian bit for
  /// bit.
  static void makeSkewHermitian(X& x) { adjointExchange(x.layout()).makeSkewHermitian(x.local()); }
  static Scalar trace(const X& x) {
    Scalar local(0.0);
    forDiagonal(x, [&](int i, int j) { local += x.local()(i, j); });
    return x.layout().grid().sum(local);
  }
  static void addToDiagonal(X& x, Scalar c) {
    forDiagonal(x, [&](int i, int j) { x.local()(i, j) += c; });
  }

  static double frobeniusNorm(const X& x) {
    return std::sqrt(x.layout().grid().sum(x.local().squaredNorm()));
  }
  static double frobeniusDistance(const X& x, const X& y) {
    return std::sqrt(x.layout().grid().sum((x.local() - y.local()).squaredNorm()));
  }
  /// ‖x‖₁ as the dense backend forms it (|z| from the squares, hypot's where they may have
  /// under- or overflowed): this rank's column sums added over the process rows on rank 0,
  /// whose largest is broadcast, so every rank has the same bits. pzlange_ took |z| by hypot,
  /// a visible share of the step (docs/design/distributed.md, "The 1-norm and the factor by
  /// solves").
  static double oneNorm(const X& x) {
    const double fast = largestColumnSum(x, false);
    return Dense::squaresWereExact(fast) ? fast : largestColumnSum(x, true);
  }
  static double innerProduct(const X& x, const X& y) {
    return x.layout().grid().sum(Dense::innerProduct(x.local(), y.local()));
  }
  static bool allFinite(const X& x) {
    return !(x.layout().grid().max(x.local().allFinite() ? 0.0 : 1.0) > 0.0);
  }
  static void flushSubnormals(X& x) { Dense::flushSubnormals(x.local()); }
  /// Every entry exactly zero on every rank (NaN is not zero, as in the dense backend).
  static bool isZero(const X& x) {
    const bool nonzero = (x.local().array() != Scalar(0.0)).any();
    return !(x.layout().grid().max(nonzero ? 1.0 : 0.0) > 0.0);
  }

  /// out(s) = x(indices(s)), column-major linear indices into the whole matrix: each entry
  /// from its owner (the others add zero, so the sum is exact), on every rank.
  template <class Indices, class Out>
  static void sampleEntries(const X& x, const Indices& indices, Out& out) {
    const BlockCyclicLayout& layout = x.layout();
    const ProcessGrid& grid = layout.grid();
    const Eigen::Index n = x.size();
    for (Eigen::Index s = 0; s < indices.size(); ++s) {
      const int i = static_cast<int>(indices(s) % n), j = static_cast<int>(indices(s) / n);
      out(s) = layout.ownerRow(i) == grid.row() && layout.ownerCol(j) == grid.col()
                   ? x.local()(layout.localRow(i), layout.localCol(j))
                   : Scalar(0.0);
    }
    MPI_Allreduce(MPI_IN_PLACE, out.data(), static_cast<int>(out.size()), MPI_C_DOUBLE_COMPLEX,
                  MPI_SUM, grid.comm());
  }

  /// x, gathered whole, into rank 0's record; the other ranks' records get an empty matrix
  /// (only rank 0's is written: docs/design/distributed.md, "Checkpoints").
  static void save(BinaryRecordWriter& out, const X& x) { out.put(x.gather()); }
  /// x ← the whole matrix of rank 0's record, scattered: the record is read on every rank
  /// through a RankZeroRecordReader, so that only rank 0 holds it whole.
  static void load(BinaryRecordReader& in, X& x) {
    auto* shared = dynamic_cast<RankZeroRecordReader*>(&in);
    if (shared == nullptr) {
      throw std::logic_error("a distributed matrix is read through a RankZeroRecordReader");
    }
    shared->getDistributed(x);
  }

 private:
  // The adjoints' plan for a layout, kept per thread and built anew when the layout changes
  // (a run has one), so that an adjoint allocates nothing.
  static AdjointExchange& adjointExchange(const BlockCyclicLayout& layout) {
    thread_local AdjointExchange plan;
    if (!plan.isFor(layout)) plan = AdjointExchange(layout);
    return plan;
  }

  // The largest Σ_i |x_ij| over the columns, |z| from the squares (MatrixBackend<Entries>::
  // fastMagnitudes) or, where `exact`, by hypot; the same on every rank, NaN if an entry is.
  static double largestColumnSum(const X& x, bool exact) {
    const BlockCyclicLayout& layout = x.layout();
    thread_local Eigen::RowVectorXd local;
    thread_local Eigen::VectorXd sums, total;
    if (exact) {
      local.noalias() = x.local().cwiseAbs().colwise().sum();
    } else {
      local.noalias() = MatrixBackend<Entries>::fastMagnitudes(x.local()).colwise().sum();
    }
    sums.setZero(x.size());
    for (int l = 0; l < layout.localCols(); ++l) sums(layout.globalCol(l)) = local(l);
    total.resize(x.size());
    MPI_Reduce(sums.data(), total.data(), x.size(), MPI_DOUBLE, MPI_SUM, 0, layout.grid().comm());
    double largest = layout.grid().rank() == 0 ? total.maxCoeff<Eigen::PropagateNaN>() : 0.0;
    MPI_Bcast(&largest, 1, MPI_DOUBLE, 0, layout.grid().comm());
    return largest;
  }

  // f(local row, local column) for every local entry on the diagonal.
  template <class F>
  static void forDiagonal(const X& x, F f) {
    const BlockCyclicLayout& layout = x.layout();
    for (int l = 0; l < layout.localCols(); ++l) {
      const int i = layout.globalCol(l);
      if (layout.ownerRow(i) == layout.grid().row()) f(layout.localRow(i), l);
    }
  }
};

}  // namespace ddb
