// fluid-relax's placements (fluid_relax/fluid_run.h): one process holds the run, writes the files
// and needs no agreement. OneProcess is what they share; CpuPlacement keeps the states in this
// process's memory (the CUDA placement, fluid_relax/cuda_run.cc, on one GPU's).
#pragma once

#include <ddb/integrators/methods/strang_splitting.h>
#include <ddb/systems/zeitlin_exact_flows.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <spdlog/fmt/fmt.h>

#include <Eigen/Core>
#include <memory>
#include <string>

#include "common/json.h"
#include "common/resume.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/options.h"
#include "fluid_relax/step_flags.h"

namespace ddb::fluid {

/// One process: every job runs here, a failure propagates at once (a write error is exit
/// status 1 through app::runMain, a UsageError 2), and every flag is this process's own.
class OneProcess {
 public:
  explicit OneProcess(Eigen::Index n) : n_(n) {}

  Eigen::Index n() const { return n_; }
  bool writes() const { return true; }
  template <class Job>
  void agreed(const Job& job) {
    job();
  }
  template <class Job>
  void onWriter(const Job& job) {
    job();
  }
  template <class Job>
  void write(const Job& job) {
    job();
  }
  bool writeFailed() const { return false; }
  void reportWriteError() const {}
  StepFlags agree(StepFlags flags) const { return flags; }
  template <class Load>
  void loadCheckpoint(Checkpoint& c, const RelaxOptions& caps, const std::string& dir,
                      const Load& load) {
    app::resumeRelaxation(c.relaxation, caps, dir, kCheckpointFile, load);
  }
  std::string describe() const { return ""; }
  std::string progressLabel() const { return ""; }
  void addToSummary(app::Json&) const {}
  std::string resumeCommand(const std::string& out) const { return "fluid-relax --resume " + out; }

 private:
  Eigen::Index n_;
};

/// The states in this process's memory: every state's spectrum drift is measured, and the
/// progress line shows ‖[P, W]‖.
class CpuPlacement : public OneProcess {
 public:
  using Group = SUN;
  using State = Matrix;
  static constexpr bool kSpectrumEveryState = true;

  CpuPlacement(Eigen::Index n, double alpha, const ZeitlinPhysics& physics)
      : OneProcess(n),
        fluid_(makeZeitlinFluid(n, alpha, physics)),
        hamiltonian_(dynamic_cast<const ZeitlinHamiltonian&>(fluid_->hamiltonian())),
        diagnostics_(hamiltonian_) {}

  const std::shared_ptr<const LiePoissonSystem<SUN>>& system() const { return fluid_; }
  const std::shared_ptr<const LiePoissonSystem<SUN>>& hostFluid() const { return fluid_; }
  const Matrix& initialState(const Matrix& W0) const { return W0; }
  const Matrix& onHost(const Matrix& W, Matrix&) const { return W; }
  std::string commutatorText(const Matrix& W) const {
    return fmt::format("  |[P,W]| {:.3g}", diagnostics_.commutatorNorm(W));
  }
  std::string device() const { return "cpu"; }
  std::unique_ptr<OneStepMethod<SUN>> splitWith(std::unique_ptr<OneStepMethod<SUN>> method,
                                                const ZeitlinDampingAndForcing& flows) const {
    for (auto& flow : zeitlinExactFlows(hamiltonian_, flows)) {
      method = std::make_unique<StrangSplitting<SUN>>(std::move(method), std::move(flow));
    }
    return method;
  }

 private:
  std::shared_ptr<const LiePoissonSystem<SUN>> fluid_;
  const ZeitlinHamiltonian& hamiltonian_;
  ZeitlinDiagnostics diagnostics_;
};

}  // namespace ddb::fluid
