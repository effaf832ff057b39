// ddb-compare's files (docs/reference/command-lines-and-files.md, "Output files"): <method>.csv as
// the run goes, summary.json and runtime_table.md from every method's result, error_vs_h.csv
// from the sweep.
#pragma once

#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/drivers/steady_state_probe.h>

#include <Eigen/Core>
#include <complex>
#include <filesystem>
#include <optional>
#include <string>

#include "common/atomic_file.h"
#include "common/csv_row.h"
#include "common/json.h"

namespace ddb::compare {

/// <method>.csv rows as they are computed (docs/reference/command-lines-and-files.md): t, μ,
/// energy, Casimirs, the step h that reached the state and its residual r (SteadyStateProbe).
template <class G>
class TrajectoryCsv {
 public:
  using Dual = typename G::template Dual<double>;

  /// `at`: relax()'s description of the state passed to operator(), kept by the caller
  /// (its h is written).
  TrajectoryCsv(app::AtomicFile& file, const LiePoissonSystem<G>& system, const RelaxState& at)
      : file_(file), system_(system), at_(at), probe_(system), row_(G::kDim + 4 + G::kNumCasimirs) {
    std::string header = "t";
    for (int i = 1; i <= G::kDim; ++i) header += ",m" + std::to_string(i);
    header += ",energy";
    if (G::kNumCasimirs == 1) {
      header += ",casimir";
    } else {
      for (int i = 1; i <= G::kNumCasimirs; ++i) header += ",casimir" + std::to_string(i);
    }
    file_.write(header + ",h,residual\n");
  }

  void operator()(long, double t, const Dual& mu) {
    row_.put(t);
    for (int i = 0; i < G::kDim; ++i) row_.put(mu(i));
    row_.put(system_.energy(mu));
    const auto c = system_.casimirs(mu);
    for (int i = 0; i < G::kNumCasimirs; ++i) row_.put(c(i));
    row_.put(at_.h);
    probe_.evaluate(mu);
    row_.put(probe_.residual());
    row_.writeTo(file_);
  }

 private:
  app::AtomicFile& file_;
  const LiePoissonSystem<G>& system_;
  const RelaxState& at_;
  SteadyStateProbe<G> probe_;
  app::CsvRow row_;
};

/// <method>.csv rows of a matrix state (SO(N), SU(N); docs/reference/command-lines-and-files.md):
/// t, energy, the spectrum's relative drift, ‖μ‖_F, the step h that reached the state and its
/// residual r. The N² entries are not written: the final state is in summary.json.
template <class G>
class MatrixTrajectoryCsv {
 public:
  using Dual = typename G::template Dual<double>;

  /// `drift`: the spectrum drift of the state passed to operator(), kept by the caller,
  /// which computes it for every state (casimir_drift is a maximum over all of them).
  /// `at` as TrajectoryCsv's.
  MatrixTrajectoryCsv(app::AtomicFile& file, const LiePoissonSystem<G>& system, const double& drift,
                      const RelaxState& at)
      : file_(file), system_(system), drift_(drift), at_(at), probe_(system), row_(6) {
    file_.write("t,energy,casimir_drift,norm,h,residual\n");
  }

  void operator()(long, double t, const Dual& mu) {
    row_.put(t);
    row_.put(system_.energy(mu));
    row_.put(drift_);
    row_.put(mu.norm());
    row_.put(at_.h);
    probe_.evaluate(mu);
    row_.put(probe_.residual());
    row_.writeTo(file_);
  }

 private:
  app::AtomicFile& file_;
  const LiePoissonSystem<G>& system_;
  const double& drift_;
  const RelaxState& at_;
  SteadyStateProbe<G> probe_;
  app::CsvRow row_;
};

/// What summary.json and runtime_table.md say of one method.
struct MethodResult {
  std::string name;
  app::Json final;  // the state: numbers, or {"re": rows, "im": rows} for a matrix
  int order = 0;    // the method table's order at the run's α
  double energy_final = 0.0;
  long steps = 0;
  double t_final = 0.0;
  std::optional<long> energy_rises;  // for the methods EnergyRises::applies to
  bool ok = true;
  std::string failed_label, failure;  // "FAILED at step k" and why, if not ok
  long failed_step = 0;
  double err_final = 0.0, casimir_drift = 0.0, runtime_s = 0.0;
  int timed_runs = 1;
  // relax()'s account (docs/guide/steady-states.md): why the run stopped, r at the final state,
  // the steps the step control rejected and the last step taken.
  std::string stop;
  bool steady = false;
  double residual_final = 0.0, h_final = 0.0;
  long steps_rejected = 0;
};

/// A state for summary.json: its numbers, or for a matrix {"re": N rows, "im": N rows}
/// (im all zeros for a real matrix).
template <class Derived>
app::Json stateJson(const Eigen::MatrixBase<Derived>& mu) {
  if constexpr (Derived::ColsAtCompileTime == 1) {
    return app::jsonArray(mu);
  } else {
    app::Json re = app::Json::array(), im = app::Json::array();
    for (Eigen::Index i = 0; i < mu.rows(); ++i) {
      const Eigen::VectorXcd row = mu.row(i).transpose().template cast<std::complex<double>>();
      re.push_back(app::jsonArray(row.real()));
      im.push_back(app::jsonArray(row.imag()));
    }
    return app::Json{{"re", re}, {"im", im}};
  }
}

/// summary.json's "methods" and "runtime_table" and runtime_table.md, method by method.
class Report {
 public:
  /// `repeat`: --repeat, named in runtime_table.md's header.
  explicit Report(int repeat);
  void add(const MethodResult& result);
  /// Writes summary.json (`head` followed by "methods" and "runtime_table") and
  /// runtime_table.md to `out`.
  void write(const std::filesystem::path& out, app::Json head) const;

 private:
  app::Json methods_ = app::Json::object();
  app::Json runtime_table_ = app::Json::object();
  std::string table_;
};

/// error_vs_h.csv: one row per method and step size of the sweep.
class SweepCsv {
 public:
  SweepCsv();
  void add(const std::string& method, double h, double err_final, double casimir_drift,
           double runtime_s);
  void write(const std::filesystem::path& out) const;

 private:
  std::string rows_;
};

}  // namespace ddb::compare
