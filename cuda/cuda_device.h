// The GPU the CUDA backend runs on (cuda/cuda_backend.h): whether there is one, its name and
// memory, and the transfers of a matrix between this process's memory and the device's, the
// only places where a value leaves the step (docs/guide/gpu.md).
#pragma once

#include <ddb/cuda/cuda_error.h>
#include <ddb/cuda/cuda_matrix.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

namespace ddb {

/// Why the CUDA backend cannot run here (no device, no driver: the runtime's words), or
/// nothing when device 0 can be used. Touches the device only to ask.
std::optional<std::string> cudaUnavailable();

/// Device 0's name, e.g. "NVIDIA H200".
std::string cudaDeviceName();

/// Bytes of device memory in use now (the whole device, every process) and in all.
struct CudaMemory {
  long long used = 0, total = 0;
};
CudaMemory cudaMemory();

/// Waits until every operation queued on the device is done (for timings).
void cudaSynchronize();

/// The host matrix m on the device, in this thread's context (CudaContext::ofThisThread()).
CudaMatrix toDevice(const Eigen::MatrixXcd& m);
/// The host matrix m on the device, in `context`.
CudaMatrix toDevice(const Eigen::MatrixXcd& m, const std::shared_ptr<CudaContext>& context);
/// x ← m's entries, in x's context (this thread's if x has none; x reallocated only when its
/// shape is not m's).
void toDevice(const Eigen::MatrixXcd& m, CudaMatrix& x);
/// x's entries in this process's memory.
Eigen::MatrixXcd toHost(const CudaMatrix& x);
/// out ← x's entries (out resized; no allocation when it has x's shape).
void toHost(const CudaMatrix& x, Eigen::MatrixXcd& out);

}  // namespace ddb
