// CudaEigenbasis: the spectral calculus of a skew-Hermitian CudaMatrix x, the CUDA backend's
// Eigenbasis (MatrixBackend<CudaMatrix>::Eigenbasis, docs/design/matrix-backend.md), on which
// the exponential's steps rest on the device (docs/reference/conventions.md §1, "Matrix
// algebras"), and the dual numbers' eigenbasis through its coordinates (toBasis, weigh, fromBasis:
// core/dual_eigenbasis.h). x = V diag(iθ) Vᴴ from the Hermitian −ix by cuSOLVER's zheevd (V and θ
// on the device, θ copied back for adRadius); apply() forms V [F ∘ (Vᴴ A V)] Vᴴ by four zgemm and
// one kernel, F_ab = f(scale (θ_a − θ_b)) (core/phase_function.h) or given weights W_ab
// (applyWeights), then projects the rounding
// onto the skew-Hermitian matrices as the dense eigenbasis does
// (core/skew_hermitian_eigenbasis.h). Workspaces are kept between decompositions of one size, in
// the decomposed matrix's context (cuda/cuda_context.h), whose matrices alone it then takes.
#pragma once

#include <ddb/core/eigenbasis_weights.h>
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
  /// hat = Vᴴ in V: `in` in the eigenbasis' coordinates (two products); hat takes in's size in
  /// the decomposed matrix's context.
  void toBasis(const CudaMatrix& in, CudaMatrix& hat);
  /// m ← w ∘ m for the named weights (core/eigenbasis_weights.h) of a matrix in the
  /// coordinates, in one kernel.
  void weigh(const PhaseFunctionWeights& w, CudaMatrix& m);
  void weigh(const ConjugationDerivativeWeights& w, CudaMatrix& m);
  void weigh(const RowPhaseWeights& w, CudaMatrix& m);
  /// out = V hat Vᴴ projected onto the skew-Hermitian matrices (two products); hat is left as
  /// it is. The inverse of toBasis on skew-Hermitian matrices.
  void fromBasis(const CudaMatrix& hat, CudaMatrix& out);
  /// The weights of applyWeights after compute(): W_ab = weight(a, b), real and symmetric,
  /// evaluated on the host and copied to the device.
  template <class Weight>
  void setWeights(const Weight& weight) {
    const Eigen::Index n = phases_.size();
    Eigen::MatrixXd weights(n, n);
    for (Eigen::Index b = 0; b < n; ++b) {
      for (Eigen::Index a = 0; a < n; ++a) weights(a, b) = weight(a, b);
    }
    uploadWeights(weights);
  }
  /// out = V [W ∘ (Vᴴ in V)] Vᴴ, projected onto the skew-Hermitian matrices; `in`
  /// skew-Hermitian. out may be in. Throws std::logic_error if no weights were set since
  /// compute().
  void applyWeights(const CudaMatrix& in, CudaMatrix& out);
  /// π_a = Im (Vᴴ y V)_aa for a skew-Hermitian y (y's eigenvalues iπ_a when y commutes with
  /// x), on the host. Two products.
  void diagonalPhasesOf(const CudaMatrix& y, Eigen::VectorXd& out);

 private:
  // Copies W (N×N) to the device, allocating its buffer on first use.
  void uploadWeights(const Eigen::MatrixXd& weights);
  // Throws std::logic_error unless rows = cols = the decomposed size.
  void requireDecomposedSize(long rows, long cols, const char* function) const;
  // Throws InvalidArgument unless x is in the decomposed matrix's context.
  void requireDecomposedContext(const CudaMatrix& x, const char* function) const;
  // out = V [F ∘ (Vᴴ in V)] Vᴴ, projected, where weigh() sets Â ← F ∘ Â on the device.
  template <class Weigh>
  void transform(const CudaMatrix& in, CudaMatrix& out, const Weigh& weigh, const char* function);
  // out = A in Aᴴ, A = op_a(V) for the cuBLAS operation op_a (Vᴴ: toBasis; V: fromBasis), two
  // products; out takes in's size in the decomposed context.
  void conjugate(const CudaMatrix& in, CudaMatrix& out, int op_a, const char* function);
  // weigh(): checks m's size and context, then kernel(state, n, θ on the device, m's reals).
  template <class Kernel>
  void weighEntries(CudaMatrix& m, const Kernel& kernel);

  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
  Eigen::VectorXd phases_;
};

}  // namespace ddb
