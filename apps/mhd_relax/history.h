// mhd-relax's history rows (docs/reference/command-lines-and-files.md, "mhd-relax"): a state's
// numbers, evaluated once, as a row of history.csv (a JournalFile: `history.csv.partial` while the
// run writes it) and a frame of fluid.hdf5 with both fields.
#pragma once

#include <ddb/core/dual_matrix.h>
#include <ddb/groups/dual_number_sun.h>
#include <ddb/integrators/drivers/steady_state_probe.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_mhd.h>

#include <Eigen/Core>
#include <optional>

#include "common/csv_row.h"
#include "common/journal_file.h"
#include "mhd_relax/checkpoint.h"
#include "mhd_relax/mhd_h5.h"
#include "mhd_relax/options.h"

namespace ddb::mhd {

using State = DualMatrix<Eigen::MatrixXcd>;

/// The largest relative drift of tr Θᵏ (k = 2, 3, 4) and tr(WΘᵏ) (k = 1, 2, 3) from the first
/// state's, over the scales N ρ_Θᵏ and N ρ_W ρ_Θᵏ (ρ: the first state's spectral norms; 1 where
/// a field is zero, which then stays zero): O(N³), where the full Casimir set costs O(N⁴).
class InvariantDrift {
 public:
  explicit InvariantDrift(const State& mu0);
  double operator()(const State& mu) const;

 private:
  /// tr Θ², tr Θ³, tr Θ⁴, tr(WΘ), tr(WΘ²), tr(WΘ³) (complex: the powers of a skew-Hermitian Θ
  /// have real or imaginary traces by parity).
  static Eigen::Matrix<std::complex<double>, 6, 1> invariants(const State& mu);

  Eigen::Matrix<std::complex<double>, 6, 1> first_;
  Eigen::Matrix<double, 6, 1> scale_;
};

class HistoryFiles {
 public:
  /// New files in s.out for the run of `o`, `s` on `system` (makeZeitlinMhd), or (`resume`)
  /// the files of a resumed run continued from the lengths its checkpoint recorded (the folder
  /// checked by checkResumeFolder). Throws IoError.
  HistoryFiles(const Options& o, const Settings& s, const LiePoissonSystem<DualNumberSUN>& system,
               const FileLengths* resume);
  /// The row of state k at time t reached by a step h (0 for k = 0).
  void write(long k, double t, double h, const State& mu);
  /// The numbers of the last row written.
  const MhdFrameNumbers& last() const { return last_; }
  /// Makes the rows written durable (before a checkpoint) and returns their lengths.
  FileLengths sync();
  /// Completes history.csv and fluid.hdf5 under their names.
  void commit();

 private:
  const ZeitlinMhdHamiltonian& hamiltonian_;
  ZeitlinMhdDiagnostics diagnostics_;
  SteadyStateProbe<DualNumberSUN> probe_;
  SphericalHarmonicBasis basis_;
  InvariantDrift drift_;
  MhdFrameNumbers last_;
  app::CsvRow row_;
  std::optional<app::JournalFile> csv_;
  std::optional<MhdH5> h5_;
};

}  // namespace ddb::mhd
