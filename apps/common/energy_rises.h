// Energy rises of a dissipative run (docs/reference/command-lines-and-files.md, "Energy rises").
// With α > 0 the flow lowers the energy (dH/dt = −k(ad*_ξ μ, ad*_ξ μ) ≤ 0) and a DDB step does too
// when h resolves the flow; a rise beyond round-off is a sign that h is too large, which
// the apps count and report instead of passing over in silence.
#pragma once

#include <ddb/core/binary_record.h>

#include <string>

namespace ddb::app {

class EnergyRises {
 public:
  // A rise E_k − E_{k−1} counts if it exceeds energyRoundOff(E_{k−1}, E_k)
  // (integrators/drivers/energy_step_control.h), the rounding the step control allows too.

  /// Whether rises are counted: a method of the DDB family (MethodInfo::keeps_casimirs,
  /// integrators/methods/method_table.h) with α > 0. Other methods, and α ≤ 0, promise no
  /// monotone energy.
  static bool applies(bool keeps_casimirs, double alpha);

  /// The energy of state k at time t, in the order of the run.
  void observe(long k, double t, double energy);
  long count() const { return count_; }
  /// Logs a warning naming `method`, the count, the first and the largest rise, if any.
  void warnIfAny(const std::string& method) const;

  /// The count so far and the last energy, for a checkpoint.
  void save(BinaryRecordWriter& out) const;
  void load(BinaryRecordReader& in);

 private:
  bool started_ = false;
  double last_ = 0.0;
  long count_ = 0;
  long first_step_ = 0;
  double first_t_ = 0.0;
  double largest_ = 0.0;
};

}  // namespace ddb::app
