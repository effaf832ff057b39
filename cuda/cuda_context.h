// CudaContext: the CUDA backend's state on one GPU (issue 55; docs/design/matrix-backend.md,
// "The CUDA backend's context"): a stream that orders every operation on the matrices made in
// it, the cuBLAS and cuSOLVER handles bound to that stream, and the device scratch of the
// reductions and samples. A CudaMatrix carries the context it was made in, solvers and
// eigenbases work in their matrices' context, and a context made by create() lives as long as
// the last of them, not as long as a thread. The operands of one operation share a context (the
// streams of two are not ordered with each other: InvalidArgument otherwise). A context serves one
// thread at a time; give each thread that steps its own.
#pragma once

#include <memory>

namespace ddb {

class CudaContext {
 public:
  /// The stream, the handles and the scratch (cuda/detail/cuda_context_state.h, for the
  /// backend's own files).
  struct State;

  /// A new context on the calling thread's current CUDA device (device 0 unless the program
  /// chose another); CudaError with the runtime's words when no device can be used.
  static std::shared_ptr<CudaContext> create();
  /// This thread's context, made on its first use: the context of toDevice(m) and of matrices
  /// made without one, which belong to it wherever they go (a matrix handed to another thread
  /// still runs in it: one thread at a time). It is never destroyed (the driver frees it with
  /// the process): a destructor at exit could run after the CUDA runtime has shut down.
  static const std::shared_ptr<CudaContext>& ofThisThread();

  ~CudaContext();
  CudaContext(const CudaContext&) = delete;
  CudaContext& operator=(const CudaContext&) = delete;

  /// Waits until every operation queued in this context is done (for timings).
  void synchronize();
  State& state() { return *state_; }

 private:
  CudaContext();
  std::unique_ptr<State> state_;
};

}  // namespace ddb
