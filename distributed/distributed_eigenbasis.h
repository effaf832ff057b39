// DistributedEigenbasis: the spectral calculus of a skew-Hermitian block-cyclic x,
// MatrixBackend<DistributedMatrix>::Eigenbasis (docs/design/matrix-backend.md), on which the
// exponential's steps rest on MPI ranks (docs/reference/conventions.md §1, "Matrix algebras").
// x = V diag(iθ) Vᴴ from the Hermitian −ix by pzheevd_ (V in x's layout, θ ascending on every
// rank); apply() forms V [F ∘ (Vᴴ A V)] Vᴴ by four pzgemm_ and a Hadamard product on each
// rank's local entries, F_ab = f(scale (θ_a − θ_b)) at their global indices, then projects
// the rounding onto the skew-Hermitian matrices as the dense eigenbasis does
// (core/skew_hermitian_eigenbasis.h). Workspaces are sized on the first decomposition of a
// layout, then reused. All functions are collective.
#pragma once

#include <ddb/core/phase_function.h>
#include <ddb/distributed/adjoint_exchange.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/distributed_product.h>
#include <ddb/distributed/scalapack.h>
#include <mpi.h>

#include <Eigen/Core>
#include <algorithm>
#include <complex>
#include <vector>

namespace ddb {

class DistributedEigenbasis {
 public:
  /// Decomposes x (skew-Hermitian). Returns false on every rank when x is not finite or the
  /// eigensolver did not converge.
  bool compute(const DistributedMatrix& x) {
    allocate(x.layout());
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
    multiplyInto(1.0, in, vectors_, 0.0, product_);                      // in V
    multiplyInto(1.0, vectors_, product_, 0.0, hat_, Factor::kAdjoint);  // Vᴴ in V
    // One loop per function, the function inlined in it.
    if (f == PhaseFunction::kCoadjointIncrement) {
      weigh([](double eta) { return expm1OfI(-eta); }, scale);
    } else {
      weigh([](double eta) { return expm1OfIOverI(-eta); }, scale);
    }
    multiplyInto(1.0, vectors_, hat_, 0.0, product_);  // V (F ∘ Â)
    if (!out.sameLayout(in)) out = DistributedMatrix(in.layout());
    multiplyInto(1.0, product_, vectors_, 0.0, out, Factor::kAsIs, Factor::kAdjoint);
    adjoints_.makeSkewHermitian(out.local());
  }

 private:
  // Â_ab ← f(scale (θ_a − θ_b)) Â_ab over this rank's entries, a and b their global indices.
  template <class Function>
  void weigh(const Function& function, double scale) {
    const BlockCyclicLayout& layout = hat_.layout();
    Eigen::MatrixXcd& local = hat_.local();
    for (int l = 0; l < layout.localCols(); ++l) {
      const double theta_b = phases_(layout.globalCol(l));
      for (int k = 0; k < layout.localRows(); ++k) {
        local(k, l) *= function(scale * (phases_(layout.globalRow(k)) - theta_b));
      }
    }
  }

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
  Eigen::VectorXd phases_;
  std::vector<std::complex<double>> work_;
  std::vector<double> rwork_;
  std::vector<int> iwork_;
  int lwork_ = 0, lrwork_ = 0, liwork_ = 0;
};

}  // namespace ddb
