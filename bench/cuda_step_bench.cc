// One method's step on Zeitlin's fluid on the GPU (cuda/cuda_zeitlin_fluid.h), timed against
// one complex N×N product on the same device (cuBLAS's zgemm) in the same run, and the Poisson
// solve alone; then, unless cpu_steps is 0, the same step on this machine's CPU (the dense
// backend, the BLAS's and the library's threads as the environment sets them) against its own
// product: products per step on each. State: the seeded random vorticity (seed 1,
// ‖W‖_F = √N; randomVorticity's, without SU(N)'s N <= 4096), α as given, h by fluid-relax's
// rule (systems/zeitlin_step_size.h) with the spectral norms from 500 power iterations on the
// device (a host eigensolver at N = 16384 would take longer than the benchmark; up to N = 2048
// the JSON gives the rule's exact h as h_default beside it); 3 untimed steps fill the
// predictor. Device memory is what the device holds after the timed steps (the
// library keeps its workspaces, so it is the run's peak). Prints one JSON object
// (docs/results/gpu.md; scripts/gpu-check.sh runs the table).
//
//   cuda-step-bench N [steps] [alpha] [method] [cpu_steps]
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_zeitlin_fluid.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_step_size.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <string>

namespace {

using namespace ddb;

// Seconds per call of f over `count` calls, the device idle before and after.
double perCall(long count, const std::function<void()>& f) {
  cudaSynchronize();
  const auto begin = std::chrono::steady_clock::now();
  for (long i = 0; i < count; ++i) f();
  cudaSynchronize();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() / count;
}

long integer(const char* text, const char* name, long least) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < least) {
    throwInvalid(name, text, "must be an integer >= " + std::to_string(least));
  }
  return value;
}

// ‖A‖₂ of a skew-Hermitian A (AᴴA = −A²) from `iterations` power iterations of A² on the
// device, from a seeded random start: a lower bound that converges to it.
double spectralNormEstimate(const CudaMatrix& A, int iterations) {
  using Device = MatrixBackend<CudaMatrix>;
  detail::NormalSource source(2);
  Eigen::MatrixXcd start(A.rows(), 1);
  for (Eigen::Index i = 0; i < start.rows(); ++i) start(i) = {source.next(), source.next()};
  CudaMatrix v = toDevice(start), w;
  for (int i = 0; i < iterations; ++i) {
    Device::divide(v, Device::frobeniusNorm(v));
    Device::multiply(A, v, w);
    Device::multiply(A, w, v);
  }
  Device::divide(v, Device::frobeniusNorm(v));
  Device::multiply(A, v, w);
  return Device::frobeniusNorm(w);
}

int runBench(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: cuda-step-bench N [steps] [alpha] [method] [cpu_steps]\n");
    return 2;
  }
  const long n = integer(argv[1], "N", 2);
  const long steps = argc > 2 ? integer(argv[2], "steps", 1) : 10;
  const double alpha = argc > 3 ? std::atof(argv[3]) : 0.5;
  const std::string method_name = argc > 4 ? argv[4] : "ddb-cay";
  const long cpu_steps = argc > 5 ? integer(argv[5], "cpu_steps", 0) : 3;
  if (const auto why = cudaUnavailable()) {
    std::fprintf(stderr, "cuda-step-bench: %s\n", why->c_str());
    return 2;
  }
  constexpr long kWarmUp = 3;
  const long long memory_before = cudaMemory().used;

  detail::NormalSource source(1);
  const Eigen::MatrixXcd W0 = detail::normalised(source.complexMatrix(n));

  CudaMatrix a = toDevice(W0), b = toDevice(W0), c;
  using Device = MatrixBackend<CudaMatrix>;
  Device::multiply(a, b, c);  // untimed: cuBLAS chooses its kernel on the first call
  const double product_s = perCall(5, [&] { Device::multiply(a, b, c); });
  CudaPoissonSolver poisson(n);
  poisson.solve(a, c);
  const double poisson_s = perCall(5, [&] { poisson.solve(a, c); });

  // h = min(0.02 ħ/‖P₀‖₂, 4ħ/(|α| ‖W₀‖₂²)), as zeitlinDefaultStep, P₀ in c.
  constexpr int kPowerIterations = 500;
  const double hbar = zeitlinHbar(n), w_norm = spectralNormEstimate(a, kPowerIterations);
  const double h =
      std::min(kZeitlinContractionRate * hbar / spectralNormEstimate(c, kPowerIterations),
               kZeitlinStiffness * hbar / (std::abs(alpha) * w_norm * w_norm));
  const std::string h_default = n <= 2048 ? std::to_string(zeitlinDefaultStep(W0, alpha)) : "null";

  const auto fluid = makeCudaZeitlinFluid(n, alpha);
  auto method = makeMethod<CudaSUN>(method_name, fluid);
  CudaMatrix W = toDevice(W0);
  long k = 0, iterations = 0;
  for (; k < kWarmUp; ++k) method->advance(W, double(k) * h, h);
  const double step_s = perCall(steps, [&] {
    method->advance(W, double(k) * h, h);
    ++k;
    iterations += method->lastStepIterations();
  });
  const long long memory_after = cudaMemory().used;

  std::string cpu = "null";
  if (cpu_steps > 0) {
    using Dense = MatrixBackend<Eigen::MatrixXcd>;
    Eigen::MatrixXcd x = W0, y = W0, z;
    Dense::multiply(x, y, z);
    const double cpu_product_s = perCall(3, [&] { Dense::multiply(x, y, z); });
    const HoppeYauLaplacian laplacian(n);
    const double cpu_poisson_s = perCall(3, [&] { laplacian.solve(x, z); });
    auto dense = makeMethod<SUN>(method_name, makeZeitlinFluid(n, alpha));
    Eigen::MatrixXcd Wd = W0;
    long j = 0;
    for (; j < kWarmUp; ++j) dense->advance(Wd, double(j) * h, h);
    const double cpu_step_s = perCall(cpu_steps, [&] {
      dense->advance(Wd, double(j) * h, h);
      ++j;
    });
    cpu = "{\"product_ms\": " + std::to_string(1e3 * cpu_product_s) +
          ", \"poisson_ms\": " + std::to_string(1e3 * cpu_poisson_s) +
          ", \"step_ms\": " + std::to_string(1e3 * cpu_step_s) +
          ", \"products_per_step\": " + std::to_string(cpu_step_s / cpu_product_s) +
          ", \"steps\": " + std::to_string(cpu_steps) + "}";
  }
  std::printf(
      "{\"device\": \"%s\", \"n\": %ld, \"alpha\": %g, \"method\": \"%s\", \"steps\": %ld, "
      "\"h\": %.6g, \"h_default\": %s, "
      "\"product_ms\": %.6g, \"poisson_ms\": %.6g, \"step_ms\": %.6g, \"products_per_step\": "
      "%.4g, \"iterations_per_step\": %.4g, \"device_memory_bytes\": %lld, \"cpu\": %s}\n",
      cudaDeviceName().c_str(), n, alpha, method_name.c_str(), steps, h, h_default.c_str(),
      1e3 * product_s, 1e3 * poisson_s, 1e3 * step_s, step_s / product_s,
      double(iterations) / double(steps), memory_after - memory_before, cpu.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return runBench(argc, argv);
  } catch (const ddb::InvalidArgument& e) {
    std::fprintf(stderr, "cuda-step-bench: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cuda-step-bench: %s\n", e.what());
    return 1;
  }
}
