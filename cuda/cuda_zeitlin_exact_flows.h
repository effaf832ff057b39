// The damping and forcing of Zeitlin's fluid for states on one GPU, in the order every placement
// splits them around a method (zeitlinExactFlowsBy, systems/zeitlin_exact_flows.h): each is the
// host's flow (ZeitlinViscousFlow, ZeitlinStochasticForcingFlow, ZeitlinFixedForcingFlow), run on
// a copy of the state in this process's memory. An advance copies the state to the host and back
// (two N² transfers), and the flow costs what it costs on the CPU (docs/results/benchmarks.md,
// "The viscous flow's implicit step"): a first placement of these flows on the device, correct
// by construction of the host's, not a device kernel (docs/guide/gpu.md).
#pragma once

#include <ddb/core/exact_flow.h>
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_zeitlin_fluid.h>
#include <ddb/systems/zeitlin_exact_flows.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ddb {

/// A flow of the dense states run for the device's: μ copied to the host, advanced there by the
/// host's flow, copied back; its record (a random stream's position) is the host flow's, so a
/// checkpoint moves between the CPU and the GPU.
class CudaHostExactFlow final : public ExactFlow<CudaSUN> {
 public:
  explicit CudaHostExactFlow(std::unique_ptr<ExactFlow<SUN>> host) : host_(std::move(host)) {}

  std::string name() const override { return host_->name(); }
  void advance(CudaMatrix& mu, double h) override {
    toHost(mu, buffer_);
    host_->advance(buffer_, h);
    toDevice(buffer_, mu);
  }
  void save(BinaryRecordWriter& out) const override { host_->save(out); }
  void load(BinaryRecordReader& in) override { host_->load(in); }

 private:
  std::unique_ptr<ExactFlow<SUN>> host_;
  Eigen::MatrixXcd buffer_;  // the state on the host, kept between steps (no allocation)
};

/// The flows of `d` for the states of a GPU fluid whose host twin has `hamiltonian` (the same n
/// and physics), innermost first. Throws InvalidArgument naming the parameter, as
/// zeitlinExactFlows.
inline std::vector<std::unique_ptr<ExactFlow<CudaSUN>>> cudaZeitlinExactFlows(
    const ZeitlinHamiltonian& hamiltonian, const ZeitlinDampingAndForcing& d) {
  std::vector<std::unique_ptr<ExactFlow<CudaSUN>>> flows;
  for (auto& host : zeitlinExactFlows(hamiltonian, d)) {
    flows.push_back(std::make_unique<CudaHostExactFlow>(std::move(host)));
  }
  return flows;
}

}  // namespace ddb
