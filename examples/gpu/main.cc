// Zeitlin's fluid on one GPU (docs/guide/gpu.md): a seeded random vorticity W₀ on the device,
// ten steps of sddb-cay (α = 0.5) by the library's Relaxation, and the final W checked against
// the same run on the CPU (to 1e-12 relative) and against W₀'s spectrum, which the step keeps
// (to 1e-12 relative). Exit status 1 if a check fails; where no GPU can be used it says why
// and exits 0, having checked nothing on a device.
//   ./app
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_zeitlin_fluid.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_step_size.h>

#include <cstdio>
#include <exception>

namespace {

constexpr int kN = 48;
constexpr double kAlpha = 0.5;

// The final state of ten steps of sddb-cay on `fluid` from `W0`.
template <class G, class State>
State relaxed(const std::shared_ptr<const ddb::LiePoissonSystem<G>>& fluid, const State& W0,
              double h) {
  const auto method = ddb::makeMethod<G>("sddb-cay", fluid);
  ddb::RelaxOptions options;
  options.max_steps = 10;
  options.tolerance = 0.0;
  ddb::Relaxation<G> run(*method, *fluid, W0, h, options);
  while (run.advance()) {
  }
  return run.current();
}

}  // namespace

int main() {
  try {
    if (const auto why = ddb::cudaUnavailable()) {
      std::printf("skipped, nothing checked on a device: %s\n", why->c_str());
      return 0;
    }
    const Eigen::MatrixXcd W0 = ddb::randomVorticity(kN, 1);
    const double h = ddb::zeitlinDefaultStep(W0, kAlpha);
    const Eigen::MatrixXcd on_gpu =
        ddb::toHost(relaxed(ddb::makeCudaZeitlinFluid(kN, kAlpha), ddb::toDevice(W0), h));
    const Eigen::MatrixXcd on_cpu = relaxed(ddb::makeZeitlinFluid(kN, kAlpha), W0, h);
    const double distance = (on_gpu - on_cpu).norm() / on_cpu.norm();
    const Eigen::VectorXd before = ddb::SUN::casimirs(W0), after = ddb::SUN::casimirs(on_gpu);
    const double drift = (after - before).norm() / before.norm();
    std::printf(
        "%s: N = %d, 10 steps of sddb-cay: |W_gpu - W_cpu|/|W_cpu| = %.2e, spectrum drift "
        "%.2e\n",
        ddb::cudaDeviceName().c_str(), kN, distance, drift);
    return distance <= 1e-12 && drift <= 1e-12 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "app: %s\n", e.what());
    return 1;
  }
}
