// EnergyStepControl: step-size control for the Casimir-keeping (DDB) methods, driven by
// the one quantity they do not keep, the energy (docs/guide/steady-states.md).
// A DDB step keeps every state on the coadjoint orbit whatever h is, so the Casimirs need
// no control; what a too large h spoils is the dissipation. The controller therefore
// accepts a step of size h from μ to μ' only if
//   (a) the step succeeded: the Legendre solve converged, the exponential stayed within
//       its injectivity limit, μ' is finite (a SolveFailure is a rejection, not an end);
//   (b) the energy moved the way the flow moves it: (H(μ') − H(μ))·sign(dH/dt) ≥ −rounding,
//       rounding = energyRoundOff(H(μ), H(μ')); a change the other way beyond rounding is
//       never accepted;
//   (c) the energy change agrees with the flow's to first order:
//       e = |ΔH/(h dH/dt(μ)) − 1| ≤ tolerance, with dH/dt(μ) = −k(ad*_ξ μ, ad*_ξ μ)
//       (Proposition 3.3). e = h Ḧ/(2Ḣ) + O(h²) is a local error estimate of the
//       dissipation. Skipped when h|dH/dt| is below rounding: there ΔH measures nothing.
// A rejected step is retried at h/2. After kGrowAfter accepted steps in a row with
// e ≤ tolerance/2, h doubles: powers of two of the first h, and h held over
// several steps, so that the Legendre solver's predictors
// (integrators/solvers/correction_predictor.h), one history per step size with four kept, have
// corrections at the h in use. Where the slow modes dominate (late relaxation), e ∝ λ_slow h
// permits large h; a fast mode that a large h makes unstable (the dissipative part of a DDB step is
// explicit) grows until (b) or (c) sees it and halves h again.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/core/detail/energy_round_off.h>
#include <ddb/core/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace ddb {

struct StepSizeControl {
  bool adaptive = false;   ///< false: every step of the first h, none rejected
  double tolerance = 0.5;  ///< on e = |ΔH/(h dH/dt) − 1|, in (0, 1)
};

class EnergyStepControl {
 public:
  /// Accepted steps in a row with e ≤ tolerance/2 before h doubles.
  static constexpr int kGrowAfter = 4;
  /// The smallest h tried, as a fraction of the first (30 halvings): below it the run fails.
  static constexpr double kMinStepFraction = 0x1p-30;

  EnergyStepControl(const StepSizeControl& control, double h0) : control_(control), h_(h0) {
    requirePositive("h", h0);
    if (!(control.tolerance > 0 && control.tolerance < 1)) {
      throwInvalid("tolerance", formatValue(control.tolerance), "must be in (0, 1)");
    }
    h_min_ = kMinStepFraction * h0;
  }

  /// The step size to try next.
  double h() const { return h_; }

  /// Empty if a step of size h from energy e0, at which the flow's dH/dt is `rate`, to
  /// energy e1 is accepted (h grows after kGrowAfter good ones); else why not (h halves).
  std::string judge(double h, double rate, double e0, double e1) {
    const double rounding = energyRoundOff(e0, e1), change = e1 - e0;
    std::string why;
    if (!std::isfinite(e1)) {
      why = "the energy is not finite";
    } else if (change * (rate < 0 ? -1.0 : 1.0) < -rounding) {
      why = "the energy moved against the flow by " + formatValue(std::abs(change));
    } else if (std::abs(h * rate) > rounding) {
      const double error = std::abs(change / (h * rate) - 1.0);
      if (error > control_.tolerance) {
        why = "energy change " + formatValue(change) + " vs h dH/dt = " + formatValue(h * rate);
      } else if (error > 0.5 * control_.tolerance) {
        good_ = 0;
        return why;
      }
    }
    if (!why.empty()) return reject(why);
    if (++good_ >= kGrowAfter) {
      good_ = 0;
      h_ *= 2.0;
    }
    return why;
  }

  /// A step that failed (a SolveFailure or a non-finite state): h halves.
  std::string reject(const std::string& why) {
    good_ = 0;
    h_ *= 0.5;
    return why;
  }

  /// Whether h has fallen below kMinStepFraction of the first h.
  bool exhausted() const { return h_ < h_min_; }

  /// The controller's state (h, its floor, the good steps in a row), for a resumed run.
  void save(BinaryRecordWriter& out) const {
    out.tag("energy step control");
    out.put(h_);
    out.put(h_min_);
    out.put(good_);
  }
  void load(BinaryRecordReader& in) {
    in.expectTag("energy step control");
    in.get(h_);
    in.get(h_min_);
    in.get(good_);
    if (!(h_ > 0 && h_min_ > 0 && good_ >= 0)) throw CorruptRecord("step control state");
  }

 private:
  StepSizeControl control_;
  double h_;
  double h_min_ = 0.0;
  int good_ = 0;
};

}  // namespace ddb
