#include "ddb_compare/report.h"

#include <cmath>

#include "common/format.h"

namespace ddb::compare {

Report::Report(int repeat)
    : table_("| method | runtime (s), median of up to " + std::to_string(repeat) +
             " runs | err_final | casimir_drift |\n|---|---|---|---|\n") {}

void Report::add(const MethodResult& r) {
  app::Json& entry = methods_[r.name];
  entry["final"] = r.final;
  entry["order"] = r.order;
  entry["energy_final"] = r.energy_final;
  entry["steps"] = r.steps;
  entry["t_final"] = r.t_final;
  if (r.energy_rises) entry["energy_rises"] = *r.energy_rises;
  entry["stop"] = r.stop;
  entry["steady"] = r.steady;
  entry["residual_final"] = r.residual_final;
  entry["steps_rejected"] = r.steps_rejected;
  entry["h_final"] = r.h_final;
  if (r.ok) {
    entry["status"] = "ok";
    entry["err_final"] = r.err_final;
    entry["casimir_drift"] = r.casimir_drift;
    entry["runtime_s"] = r.runtime_s;
    entry["timed_runs"] = r.timed_runs;
    runtime_table_[r.name] = r.runtime_s;
    table_ += "| " + r.name + " | " + app::number(r.runtime_s, std::chars_format::general, 4) +
              " | " + app::number(r.err_final, std::chars_format::scientific, 3) + " | " +
              app::number(r.casimir_drift, std::chars_format::scientific, 3) + " |\n";
  } else {
    // A failed run has no final error, drift or runtime to compare: say FAILED instead.
    entry["status"] = "FAILED";
    entry["failed_step"] = r.failed_step;
    entry["err_final"] = NAN;
    entry["casimir_drift"] = NAN;
    entry["runtime_s"] = NAN;
    entry["failure"] = r.failure;
    runtime_table_[r.name] = r.failed_label;
    table_ += "| " + r.name + " | " + r.failed_label + " | - | - |\n";
  }
}

void Report::write(const std::filesystem::path& out, app::Json head) const {
  head["methods"] = methods_;
  head["runtime_table"] = runtime_table_;
  app::writeJsonFile(out / "summary.json", head);
  app::writeFileAtomically(out / "runtime_table.md", table_);
}

SweepCsv::SweepCsv() : rows_("method,h,err_final,casimir_drift,runtime_s\n") {}

void SweepCsv::add(const std::string& method, double h, double err_final, double casimir_drift,
                   double runtime_s) {
  rows_ += method + "," + app::number(h) + "," + app::number(err_final) + "," +
           app::number(casimir_drift) + "," + app::number(runtime_s) + "\n";
}

void SweepCsv::write(const std::filesystem::path& out) const {
  app::writeFileAtomically(out / "error_vs_h.csv", rows_);
}

}  // namespace ddb::compare
