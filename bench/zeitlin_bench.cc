// One step of a method on Zeitlin's fluid, N = 32..256, against one complex N×N product
// (zeitlin/gemm/<N>) in the same run: products per step = step time / product time
// (scripts/bench_ratios.py). State: the seeded random vorticity (seed 1, ‖W‖_F = √N),
// h = 0.02 ħ/‖P₀‖₂, Legendre tolerance 1e-12 relative. Counters: iterations (fixed-point
// sweeps and Newton steps) and Krylov products per step, and mallocs per step. The BLAS
// thread count is the environment's (OPENBLAS_NUM_THREADS).
#include "zeitlin_bench.h"

#include <benchmark/benchmark.h>
#include <ddb/integrators/ddb.h>
#include <ddb/integrators/method_registry.h>
#include <ddb/integrators/symmetric_ddb.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>

#include <Eigen/SVD>
#include <memory>
#include <string>

#include "malloc_counter.h"

namespace ddb::bench {
namespace {

using Matrix = Eigen::MatrixXcd;
constexpr int kSizes[] = {32, 64, 128, 256};
constexpr double kTolerance = 1e-12;

double benchmarkStep(const Matrix& W) {
  const ZeitlinHamiltonian hamiltonian(W.rows());
  const Eigen::JacobiSVD<Matrix> svd(hamiltonian.streamMatrix(W));
  return 0.02 * hamiltonian.hbar() / svd.singularValues()(0);
}

std::unique_ptr<OneStepMethod<SUN>> makeBenchMethod(
    const std::string& name, std::shared_ptr<const LiePoissonSystem<SUN>> fluid) {
  SolverOptions options;
  options.relative_tolerance = kTolerance;
  if (name == "ddb-cay") {
    return std::make_unique<Ddb<Cayley<SUN>>>(fluid, Cayley<SUN>(), LegendreForm::kHamiltonian,
                                              options);
  }
  if (name == "sddb-cay") {
    return std::make_unique<SymmetricDdb<Cayley<SUN>>>(fluid, Cayley<SUN>(),
                                                       LegendreForm::kHamiltonian, options);
  }
  return makeMethod<SUN>(name, fluid);
}

void stepFluid(benchmark::State& state, const std::string& method_name, double alpha, int n) {
  const auto fluid = makeZeitlinFluid(n, alpha);
  Matrix W = randomVorticity(n, 1);
  const double h = benchmarkStep(W);
  auto method = makeBenchMethod(method_name, fluid);
  auto* legendre = dynamic_cast<LegendreMethod<Cayley<SUN>>*>(method.get());
  method->advance(W, 0.0, h);  // sizes the workspaces
  long steps = 0, iterations = 0, krylov = 0;
  const long mallocs = tools::mallocCount();
  for (auto _ : state) {
    try {
      method->advance(W, steps * h, h);
    } catch (const SolveFailure& failure) {
      state.SkipWithError(failure.what());
      return;
    }
    benchmark::DoNotOptimize(W.data());
    ++steps;
    if (legendre != nullptr) {
      const auto& stats = legendre->legendreSolver().stats();
      iterations += stats.fixed_point + stats.newton;
      krylov += stats.krylov;
    }
  }
  const long allocated = tools::mallocCount() - mallocs;  // before the counters' own
  const double per_step = 1.0 / static_cast<double>(steps);
  state.counters["iterations_per_step"] = static_cast<double>(iterations) * per_step;
  state.counters["krylov_per_step"] = static_cast<double>(krylov) * per_step;
  state.counters["allocs_per_step"] = static_cast<double>(allocated) * per_step;
}

void product(benchmark::State& state, int n) {
  const Matrix A = randomVorticity(n, 2), B = randomVorticity(n, 3);
  Matrix C(n, n);
  for (auto _ : state) {
    C.noalias() = A * B;
    benchmark::DoNotOptimize(C.data());
  }
}

}  // namespace

void registerZeitlinBenchmarks() {
  for (int n : kSizes) {
    const std::string size = "/" + std::to_string(n);
    benchmark::RegisterBenchmark(("zeitlin/gemm" + size).c_str(), product, n)
        ->Unit(benchmark::kMicrosecond);
    for (const char* method : {"ddb-cay", "sddb-cay", "rk4"}) {
      benchmark::RegisterBenchmark(("zeitlin/" + std::string(method) + size).c_str(), stepFluid,
                                   std::string(method), 0.5, n)
          ->Unit(benchmark::kMicrosecond);
    }
    benchmark::RegisterBenchmark(("zeitlin-euler/ddb-cay" + size).c_str(), stepFluid,
                                 std::string("ddb-cay"), 0.0, n)
        ->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace ddb::bench
