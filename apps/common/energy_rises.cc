#include "common/energy_rises.h"

#include <ddb/integrators/drivers/energy_step_control.h>
#include <spdlog/spdlog.h>

#include <algorithm>

namespace ddb::app {

bool EnergyRises::applies(bool keeps_casimirs, double alpha) { return keeps_casimirs && alpha > 0; }

void EnergyRises::observe(long k, double t, double energy) {
  if (started_) {
    const double rise = energy - last_;
    if (rise > energyRoundOff(last_, energy)) {
      if (count_ == 0) {
        first_step_ = k;
        first_t_ = t;
      }
      ++count_;
      largest_ = std::max(largest_, rise);
    }
  }
  started_ = true;
  last_ = energy;
}

void EnergyRises::warnIfAny(const std::string& method) const {
  if (count_ == 0) return;
  spdlog::warn(
      "{}: the energy rose beyond round-off in {} steps (first at step {}, t = {}; largest "
      "rise {:.3g}) although alpha > 0: h is probably too large",
      method, count_, first_step_, first_t_, largest_);
}

void EnergyRises::save(BinaryRecordWriter& out) const {
  out.tag("energy rises");
  out.put(started_);
  out.put(last_);
  out.put(count_);
  out.put(first_step_);
  out.put(first_t_);
  out.put(largest_);
}

void EnergyRises::load(BinaryRecordReader& in) {
  in.expectTag("energy rises");
  in.get(started_);
  in.get(last_);
  in.get(count_);
  in.get(first_step_);
  in.get(first_t_);
  in.get(largest_);
}

}  // namespace ddb::app
