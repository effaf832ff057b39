// CudaEigenbasis: the spectral calculus of a skew-Hermitian CudaMatrix x, the CUDA backend's
// Eigenbasis (MatrixBackend<CudaMatrix>::Eigenbasis, docs/design/matrix-backend.md), on which
// the exponential's steps rest on the device (docs/reference/conventions.md §1, "Matrix
// algebras"). x = V diag(iθ) Vᴴ from the Hermitian −ix by cuSOLVER's zheevd (V and θ on the
// device, θ copied back for adRadius); apply() forms V [F ∘ (Vᴴ A V)] Vᴴ by four zgemm and
// one kernel, F_ab = f(scale (θ_a − θ_b)) (core/phase_function.h), then projects the rounding
// onto the skew-Hermitian matrices as the dense eigenbasis does
// (core/skew_hermitian_eigenbasis.h). Workspaces are kept between decompositions of one size.
#pragma once

#include <ddb/core/phase_function.h>
#include <ddb/cuda/cuda_matrix.h>

#include <Eigen/Core>
#include <memory>

namespace ddb {

class CudaEigenbasis {
 public:
  CudaEigenbasis();
  ~CudaEigenbasis();
  CudaEigenbasis(CudaEigenbasis&&) noexcept;
  CudaEigenbasis& operator=(CudaEigenbasis&&) noexcept;

  /// Decomposes x (skew-Hermitian). Returns false when x is not finite or the eigensolver
  /// did not converge.
  bool compute(const CudaMatrix& x);
  /// θ, ascending (a host copy).
  const Eigen::VectorXd& phases() const { return phases_; }
  /// max_ab |θ_a − θ_b|: the spectral radius of ad_x.
  double adRadius() const { return phases_(phases_.size() - 1) - phases_(0); }
  /// out = V [F ∘ (Vᴴ in V)] Vᴴ with F_ab = f(scale (θ_a − θ_b)), projected onto the
  /// skew-Hermitian matrices; `in` skew-Hermitian. out may be in.
  void apply(PhaseFunction f, double scale, const CudaMatrix& in, CudaMatrix& out);

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
  Eigen::VectorXd phases_;
};

}  // namespace ddb
