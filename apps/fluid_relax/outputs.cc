#include "fluid_relax/outputs.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <string>
#include <vector>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/plot.h"
#include "fluid_relax/checkpoint.h"

namespace ddb::fluid {

HistoryCsv::HistoryCsv(const std::filesystem::path& path)
    : file_(path), row_(8), gamma_column_(true) {
  file_.write("t,energy,enstrophy,commutator_norm,spectrum_drift,h,residual,gamma\n");
}

HistoryCsv::HistoryCsv(const std::filesystem::path& path, std::uint64_t length,
                       std::uint64_t digest, bool gamma_column)
    : file_(path, length, digest), row_(gamma_column ? 8 : 7), gamma_column_(gamma_column) {}

void HistoryCsv::write(double t, double energy, double enstrophy, double commutator_norm,
                       double spectrum_drift, double h, double residual, double gamma) {
  row_.put(t);
  row_.put(energy);
  row_.put(enstrophy);
  row_.put(commutator_norm);
  row_.put(spectrum_drift);
  row_.put(h);
  row_.put(residual);
  if (gamma_column_) row_.put(gamma);
  row_.writeTo(file_);
}

HistoryFiles::HistoryFiles(const Options& o, const Settings& s, const LiePoissonSystem<SUN>& system,
                           const Checkpoint* resume)
    : hamiltonian_(dynamic_cast<const ZeitlinHamiltonian&>(system.hamiltonian())),
      diagnostics_(hamiltonian_),
      probe_(system),
      basis_(hamiltonian_.laplacian()),
      gamma_(basis_),
      field_diagnostics_(resume == nullptr || resume->files.field_diagnostics) {
  if (resume != nullptr) {
    csv_.emplace(s.out / kHistoryCsv, resume->files.history_bytes,
                 resume->files.history_digest.value(), field_diagnostics_);
  } else {
    csv_.emplace(s.out / kHistoryCsv);
  }
  if (o.h5 || o.animate) {
    h5_ = resume != nullptr
              ? FluidH5::reopen(s.out / kFluidH5, resume->files.h5_frames, field_diagnostics_)
              : FluidH5::create(s.out / kFluidH5, h5Attributes(o, s, hamiltonian_.hbar()));
    if (field_diagnostics_) grid_.emplace(hamiltonian_.laplacian().size());
  }
}

void HistoryFiles::write(long k, double t, double h, const Eigen::MatrixXcd& Q, double drift) {
  probe_.evaluate(Q);
  const double energy = diagnostics_.energy(Q), enstrophy = diagnostics_.enstrophy(Q),
               commutator = diagnostics_.commutatorNorm(Q);
  // The field diagnostics are of the relative vorticity, W = Q − F (Q itself on a resting
  // sphere); γ in O(N²), the coefficients (O(N³), "Cost" in
  // docs/reference/command-lines-and-files.md) only for a frame of fluid.hdf5.
  const Eigen::MatrixXcd& W = hamiltonian_.relativeVorticity(Q, relative_);
  const double gamma = gamma_(W);
  csv_->write(t, energy, enstrophy, commutator, drift, h, probe_.residual(), gamma);
  if (!h5_) return;
  omega_ = basis_.coefficients(W);
  if (!h5_->fields()) {
    h5_->append({k, t, W, omega_, energy, enstrophy, commutator, drift});
    return;
  }
  // With --h5 also the spectra, the scale decomposition (an eigendecomposition of ψ) and the
  // grid, per frame.
  const ZeitlinSpectra spectra = zeitlinSpectra(omega_, hamiltonian_.laplacian().kappaSquared());
  hamiltonian_.streamInto(Q, stream_);
  const ScaleDecomposition scales = zeitlinScaleDecomposition(W, stream_);
  const double to_enstrophy = 1.0 / (2.0 * double(W.rows()));
  const Eigen::MatrixXd grid = grid_->evaluate(omega_);
  const FluidH5Fields fields{gamma,
                             spectra.energy,
                             spectra.enstrophy,
                             scales.steady.squaredNorm() * to_enstrophy,
                             scales.remainder.squaredNorm() * to_enstrophy,
                             grid};
  h5_->append({k, t, W, omega_, energy, enstrophy, commutator, drift, &fields});
}

HistoryFiles::Lengths HistoryFiles::sync() {
  Lengths lengths;
  lengths.history_bytes = csv_->sync();
  lengths.history_digest = csv_->digest();
  lengths.field_diagnostics = field_diagnostics_;
  if (h5_) {
    h5_->flush();
    lengths.h5_frames = h5_->frames();
  }
  return lengths;
}

void HistoryFiles::commit() {
  csv_->commit();
  if (h5_) h5_->flush();
}

int makeFigures(const Options& o, const std::filesystem::path& out, int status,
                const char* plot_script, const char* animate_script) {
  const bool figures_asked = o.plot || o.animate;
  if (status != app::kExitOk) {
    if (figures_asked && status == app::kExitFailed) spdlog::error("no figures: the run failed");
    return status;
  }
  std::vector<std::string> failures;
  if (o.animate) {
    failures.push_back(app::runPlotScript(
        animate_script, {(out / kFluidH5).string(), (out / "fluid.mp4").string()}));
  }
  if (o.plot) failures.push_back(app::runPlotScript(plot_script, out));
  failures.erase(std::remove(failures.begin(), failures.end(), ""), failures.end());
  if (failures.empty()) return app::kExitOk;
  return app::recordFiguresFailure(out / "summary.json",
                                   fmt::format("{}", fmt::join(failures, "; ")));
}

FluidH5Attributes h5Attributes(const Options& o, const Settings& s, double hbar) {
  FluidH5Attributes a;
  a.n = s.W0.rows();
  a.alpha = s.alpha;
  a.h = s.h;
  a.hbar = hbar;
  a.method = o.method;
  a.init = s.init;
  if (s.init == "file") {
    a.init_file = o.init_file;
  } else {
    a.seed = o.seed;
  }
  a.version = app::projectVersion();
  a.created = app::hdf5::utcNow();
  return a;
}

void writeOmegaCsv(const std::filesystem::path& path, const SphericalHarmonicBasis& basis,
                   const Eigen::MatrixXcd& W) {
  const Eigen::VectorXd omega = basis.coefficients(W);
  app::AtomicFile file(path);
  file.write("l,m,omega\n");
  app::CsvRow row(3);
  for (Eigen::Index l = 0; l < basis.size(); ++l) {
    for (Eigen::Index m = -l; m <= l; ++m) {
      row.put(static_cast<double>(l));
      row.put(static_cast<double>(m));
      row.put(omega(SphericalHarmonicBasis::index(l, m)));
      row.writeTo(file);
    }
  }
  file.commit();
}

}  // namespace ddb::fluid
