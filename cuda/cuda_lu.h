// LU factors and solves of a CudaMatrix with cuSOLVER (zgetrf, zgetrs), the CUDA backend's Lu
// (docs/design/matrix-backend.md, "Types"): the pivots, the status word and cuSOLVER's
// workspace are kept between factorisations of one size, so a step allocates nothing.
#pragma once

#include <ddb/cuda/cuda_matrix.h>

#include <memory>

namespace ddb {

class CudaLu {
 public:
  CudaLu();
  ~CudaLu();
  CudaLu(CudaLu&&) noexcept;
  CudaLu& operator=(CudaLu&&) noexcept;

  /// Factors a in place; false when a is singular (a zero pivot).
  bool factor(CudaMatrix& a);
  /// b ← a⁻¹b with `factored` from factor().
  void solve(const CudaMatrix& factored, CudaMatrix& b);

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

}  // namespace ddb
