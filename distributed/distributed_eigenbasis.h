// DistributedEigenbasis: the spectral calculus of a skew-Hermitian block-cyclic x,
// MatrixBackend<DistributedMatrix>::Eigenbasis (docs/design/matrix-backend.md), on which the
// exponential's steps rest on MPI ranks (docs/reference/conventions.md §1, "Matrix algebras").
// x = V diag(iθ) Vᴴ from the Hermitian −ix by pzheevd_ (V in x's layout, θ ascending on every
// rank); apply() forms V [F ∘ (Vᴴ A V)] Vᴴ by four pzgemm_ and a Hadamard product on each
// rank's local entries, F_ab = f(scale (θ_a − θ_b)) at their global indices (or given
// weights W_ab, applyWeights), then projects
// the rounding onto the skew-Hermitian matrices as the dense eigenbasis does
// (core/skew_hermitian_eigenbasis.h). Workspaces are sized on the first decomposition of a
// layout, then reused. All functions are collective.
#pragma once

#include <ddb/core/detail/weigh_on_host.h>
#include <ddb/core/phase_function.h>
#include <ddb/distributed/adjoint_exchange.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/distributed_product.h>
#include <ddb/distributed/scalapack.h>
#include <mpi.h>

#include <Eigen/Core>
#include <algorithm>
#include <complex>
#include <stdexcept>
#include <vector>

namespace ddb {

class DistributedEigenbasis {
 public:
  /// Decomposes x (skew-Hermitian). Returns false on every rank when x is not finite or the
  /// eigensolver did not converge.
  bool compute(const DistributedMatrix& x) {
    allocate(x.layout());
    weighted_ = false;  // a new basis takes new weights
    const ProcessGrid& grid = x.layout().grid();
    if (grid.max(x.local().allFinite() ? 0.0 : 1.0) > 0.0) return false;
    // −ix: (re, im) ↦ (im, −re), exact.
    hermitian_.local() = x.local() * std::complex<double>(0.0, -1.0);
    const int n = x.size(), one = 1;
    int info = 0;
    pzheevd_("V", "L", &n, hermitian_.data(), &one, &one, hermitian_.descriptor(), phases_.data(),
             vectors_.data(), &one, &one, vectors_.descriptor(), work_.data(), &lwork_,
             rwork_.data(), &lrwork_, iwork_.data(), &liwork_, &info);
    if (grid.max(info != 0 ? 1.0 : 0.0) > 0.0) return false;
    // θ from rank 0 on every rank: pzheevd_ leaves the eigenvalues on every rank only when
    // its tridiagonal solver runs distributed (for N ≤ the block size PDSTEDC runs on process
    // (0, 0) alone), and every rank's branches on θ must agree to the bit.
    MPI_Bcast(phases_.data(), n, MPI_DOUBLE, 0, grid.comm());
    return true;
  }

  /// θ, ascending, on every rank.
  const Eigen::VectorXd& phases() const { return phases_; }
  /// max_ab |θ_a − θ_b|: the spectral radius of ad_x.
  double adRadius() const { return phases_(phases_.size() - 1) - phases_(0); }

  /// out = V [F ∘ (Vᴴ in V)] Vᴴ with F_ab = f(scale (θ_a − θ_b)) (core/phase_function.h),
  /// projected onto the skew-Hermitian matrices; `in` skew-Hermitian. out may be in.
  void apply(PhaseFunction f, double scale, const DistributedMatrix& in, DistributedMatrix& out) {
    // One loop per function, the function inlined in it.
    if (f == PhaseFunction::kCoadjointIncrement) {
      transform(in, out, [&](int k, int l) {
        return expm1OfI(-(scale * (phases_(rowOf(k)) - phases_(colOf(l)))));
      });
    } else {
      transform(in, out, [&](int k, int l) {
        return expm1OfIOverI(-(scale * (phases_(rowOf(k)) - phases_(colOf(l)))));
      });
    }
  }

  /// The weights of applyWeights after compute(): W_ab = weight(a, b), real and symmetric,
  /// the same function on every rank, evaluated at this rank's entries only.
  template <class Weight>
  void setWeights(const Weight& weight) {
    const BlockCyclicLayout& layout = hat_.layout();
    local_weights_.resize(layout.localRows(), layout.localCols());
    for (int l = 0; l < layout.localCols(); ++l) {
      for (int k = 0; k < layout.localRows(); ++k) {
        local_weights_(k, l) = weight(rowOf(k), colOf(l));
      }
    }
    weighted_ = true;
  }
  /// out = V [W ∘ (Vᴴ in V)] Vᴴ, projected onto the skew-Hermitian matrices; `in`
  /// skew-Hermitian. out may be in. Throws std::logic_error (on every rank alike) if no
  /// weights were set since compute().
  void applyWeights(const DistributedMatrix& in, DistributedMatrix& out) {
    if (!weighted_ || !in.sameLayout(hat_)) {
      throw std::logic_error("DistributedEigenbasis::applyWeights: no weights for this basis");
    }
    transform(in, out, [&](int k, int l) { return local_weights_(k, l); });
  }

  /// hat = Vᴴ in V: `in` in the eigenbasis (two products); hat takes in's layout.
  void toBasis(const DistributedMatrix& in, DistributedMatrix& hat) {
    if (!hat.sameLayout(in)) hat = DistributedMatrix(in.layout());
    multiplyInto(1.0, in, vectors_, 0.0, product_);                     // in V
    multiplyInto(1.0, vectors_, product_, 0.0, hat, Factor::kAdjoint);  // Vᴴ in V
  }

  /// m_ab ← f(a, b, m_ab) for this rank's entries of a matrix in the eigenbasis' coordinates, at
  /// their global indices.
  template <class F>
  void mapEntries(DistributedMatrix& m, const F& f) const {
    Eigen::MatrixXcd& local = m.local();
    for (int l = 0; l < local.cols(); ++l) {
      for (int k = 0; k < local.rows(); ++k) local(k, l) = f(rowOf(k), colOf(l), local(k, l));
    }
  }

  /// m ← w ∘ m for the named weights of a matrix in the eigenbasis' coordinates, this rank's
  /// entries (core/eigenbasis_weights.h).
  template <class Weights>
  void weigh(const Weights& w, DistributedMatrix& m) {
    detail::weighOnHost(w, phases_, half_, [&](const auto& f) { mapEntries(m, f); });
  }

  /// out = V hat Vᴴ projected onto the skew-Hermitian matrices (two products); hat is left
  /// as it is. The inverse of toBasis on skew-Hermitian matrices.
  void fromBasis(DistributedMatrix& hat, DistributedMatrix& out) {
    multiplyInto(1.0, vectors_, hat, 0.0, product_);  // V hat
    if (!out.sameLayout(hat)) out = DistributedMatrix(hat.layout());
    multiplyInto(1.0, product_, vectors_, 0.0, out, Factor::kAsIs, Factor::kAdjoint);
    adjoints_.makeSkewHermitian(out.local());
  }

  /// The phases of a skew-Hermitian y on x's eigenvectors, on every rank: π_a = Im (Vᴴ y V)_aa
  /// (y's eigenvalues iπ_a when y commutes with x). Two products.
  void diagonalPhasesOf(const DistributedMatrix& y, Eigen::VectorXd& out) {
    multiplyInto(1.0, y, vectors_, 0.0, product_);                       // y V
    multiplyInto(1.0, vectors_, product_, 0.0, hat_, Factor::kAdjoint);  // Vᴴ y V
    const BlockCyclicLayout& layout = hat_.layout();
    diagonal_.setZero(layout.size());
    for (int l = 0; l < layout.localCols(); ++l) {
      for (int k = 0; k < layout.localRows(); ++k) {
        if (rowOf(k) == colOf(l)) diagonal_(rowOf(k)) = hat_.local()(k, l).imag();
      }
    }
    // Each entry is held by one rank and zero on the others: the sum is that entry, exactly.
    out.resize(layout.size());
    MPI_Allreduce(diagonal_.data(), out.data(), layout.size(), MPI_DOUBLE, MPI_SUM,
                  layout.grid().comm());
  }

 private:
  // out = V [F ∘ (Vᴴ in V)] Vᴴ, projected, with F at this rank's local entry (k, l) of Â
  // weight(k, l).
  template <class Weight>
  void transform(const DistributedMatrix& in, DistributedMatrix& out, const Weight& weight) {
    toBasis(in, hat_);
    Eigen::MatrixXcd& local = hat_.local();
    for (int l = 0; l < local.cols(); ++l) {
      for (int k = 0; k < local.rows(); ++k) local(k, l) *= weight(k, l);
    }
    fromBasis(hat_, out);
  }

  // The global row and column of this rank's local row k and column l.
  int rowOf(int k) const { return hat_.layout().globalRow(k); }
  int colOf(int l) const { return hat_.layout().globalCol(l); }

  // The matrices and pzheevd_'s workspaces for a layout: its query, the real and integer
  // workspaces raised to the minima its documentation states (LRWORK ≥ 1 + 9N + 3·NP·NQ,
  // LIWORK ≥ 7N + 8·NPCOL + 2), in case a release under-reports them.
  void allocate(const BlockCyclicLayout& layout) {
    if (adjoints_.isFor(layout)) return;
    for (DistributedMatrix* m : {&hermitian_, &vectors_, &product_, &hat_}) {
      *m = DistributedMatrix(layout);
    }
    adjoints_ = AdjointExchange(layout);
    const int n = layout.size(), one = 1, query = -1;
    phases_.setZero(n);
    std::complex<double> work_size;
    double rwork_size = 0.0;
    int iwork_size = 0, info = 0;
    pzheevd_("V", "L", &n, hermitian_.data(), &one, &one, hermitian_.descriptor(), phases_.data(),
             vectors_.data(), &one, &one, vectors_.descriptor(), &work_size, &query, &rwork_size,
             &query, &iwork_size, &query, &info);
    const int local_entries = layout.localRows() * layout.localCols();
    lwork_ = std::max(static_cast<int>(work_size.real()), 1);
    lrwork_ = std::max(static_cast<int>(rwork_size), 1 + 9 * n + 3 * local_entries);
    liwork_ = std::max(iwork_size, 7 * n + 8 * layout.grid().cols() + 2);
    work_.resize(static_cast<std::size_t>(lwork_));
    rwork_.resize(static_cast<std::size_t>(lrwork_));
    iwork_.resize(static_cast<std::size_t>(liwork_));
  }

  DistributedMatrix hermitian_, vectors_, product_, hat_;
  AdjointExchange adjoints_;
  Eigen::VectorXd phases_, diagonal_;
  Eigen::MatrixXd local_weights_;  // of applyWeights, at this rank's entries
  Eigen::VectorXcd half_;          // weigh()'s half phases
  bool weighted_ = false;          // local_weights_ are this basis's
  std::vector<std::complex<double>> work_;
  std::vector<double> rwork_;
  std::vector<int> iwork_;
  int lwork_ = 0, lrwork_ = 0, liwork_ = 0;
};

}  // namespace ddb
