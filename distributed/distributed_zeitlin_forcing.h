// The forcings of Zeitlin's fluid (systems/zeitlin_forcing.h) on a block-cyclic state
// (docs/design/distributed.md, "Viscosity and forcing"). Neither needs a message: each rank adds
// what falls in its own entries.
//   stochastic: every rank draws the kick's coefficients c_j (ZeitlinForcingBand: a function of
//               the seed, the kick's count and the mode, so every rank has the same) and adds
//               c_j T_j to the entries of the band's modes that it holds, in the serial flow's
//               order, so that the sum is the serial flow's to the bit on any number of ranks;
//   fixed:      W ← W + h Φ on each rank's block-cyclic part of Φ.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/exact_flow.h>
#include <ddb/distributed/distributed_zeitlin_fluid.h>
#include <ddb/systems/zeitlin_forcing.h>

#include <Eigen/Core>
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

namespace ddb {

class DistributedZeitlinStochasticForcingFlow final
    : public ZeitlinStochasticForcingStream<DistributedSUN> {
 public:
  /// The forcing on states of `layout` for a fluid of κ² (ZeitlinPhysics::kappaSquared); the same
  /// arguments on every rank. Throws InvalidArgument naming the parameter, on every rank alike.
  DistributedZeitlinStochasticForcingFlow(const BlockCyclicLayout& layout,
                                          const ZeitlinStochasticForcing& forcing,
                                          double kappa_squared = 0.0)
      : ZeitlinStochasticForcingStream<DistributedSUN>(layout.size(), forcing, kappa_squared) {
    const int my_row = layout.grid().row(), my_col = layout.grid().col();
    const auto& modes = band().modes();
    for (std::size_t j = 0; j < modes.size(); ++j) {
      const ZeitlinForcingBand::Mode& mode = modes[j];
      const auto add = [&](Eigen::Index k, bool upper) {
        const int i = int(upper ? k : k + mode.offset), col = int(upper ? k + mode.offset : k);
        if (layout.ownerRow(i) != my_row || layout.ownerCol(col) != my_col) return;
        entries_.push_back(
            {layout.localRow(i) + Eigen::Index(layout.localRows()) * layout.localCol(col), j,
             upper ? mode.upper(k) : mode.lower(k)});
      };
      for (Eigen::Index k = 0; k < mode.upper.size(); ++k) add(k, true);
      if (mode.offset != 0) {
        for (Eigen::Index k = 0; k < mode.lower.size(); ++k) add(k, false);
      }
    }
  }

  /// W ← W + σ √h Σ g_lm T_lm, the next kick of the stream (no message between ranks).
  void advance(DistributedMatrix& W, double h) override {
    const Eigen::VectorXd& c = nextKick(h);
    std::complex<double>* local = W.local().data();
    for (const Entry& e : entries_) local[e.index] += c(Eigen::Index(e.mode)) * e.value;
  }

 private:
  /// Mode `mode`'s value at this rank's local entry `index` (column-major), in the modes' order.
  struct Entry {
    Eigen::Index index;
    std::size_t mode;
    std::complex<double> value;
  };

  std::vector<Entry> entries_;
};

class DistributedZeitlinFixedForcingFlow final : public ExactFlow<DistributedSUN> {
 public:
  /// Φ whole on every rank (the same matrix; this rank keeps its block-cyclic part). Throws
  /// InvalidArgument naming "forcing" as ZeitlinFixedForcingFlow does, on every rank alike.
  DistributedZeitlinFixedForcingFlow(const BlockCyclicLayout& layout,
                                     const Eigen::MatrixXcd& forcing)
      : forcing_(layout) {
    ZeitlinFixedForcingFlow::requireValid(layout.size(), forcing);
    Eigen::MatrixXcd& local = forcing_.local();
    for (int lj = 0; lj < layout.localCols(); ++lj) {
      for (int li = 0; li < layout.localRows(); ++li) {
        local(li, lj) = forcing(layout.globalRow(li), layout.globalCol(lj));
      }
    }
  }

  std::string name() const override { return "forcing"; }
  void advance(DistributedMatrix& W, double h) override { W.local() += h * forcing_.local(); }

 private:
  DistributedMatrix forcing_;  // Φ's block-cyclic part
};

}  // namespace ddb
