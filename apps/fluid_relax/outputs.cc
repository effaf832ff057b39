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

HistoryCsv::HistoryCsv(const std::filesystem::path& path) : file_(path), row_(7) {
  file_.write("t,energy,enstrophy,commutator_norm,spectrum_drift,h,residual\n");
}

HistoryCsv::HistoryCsv(const std::filesystem::path& path, std::uint64_t length,
                       std::uint64_t digest)
    : file_(path, length, digest), row_(7) {}

void HistoryCsv::write(double t, double energy, double enstrophy, double commutator_norm,
                       double spectrum_drift, double h, double residual) {
  row_.put(t);
  row_.put(energy);
  row_.put(enstrophy);
  row_.put(commutator_norm);
  row_.put(spectrum_drift);
  row_.put(h);
  row_.put(residual);
  row_.writeTo(file_);
}

HistoryFiles::HistoryFiles(const Options& o, const Settings& s, const LiePoissonSystem<SUN>& system,
                           const Checkpoint* resume)
    : hamiltonian_(dynamic_cast<const ZeitlinHamiltonian&>(system.hamiltonian())),
      diagnostics_(hamiltonian_),
      probe_(system),
      basis_(hamiltonian_.laplacian()) {
  if (resume != nullptr) {
    csv_.emplace(s.out / kHistoryCsv, resume->files.history_bytes,
                 resume->files.history_digest.value());
  } else {
    csv_.emplace(s.out / kHistoryCsv);
  }
  if (o.h5 || o.animate) {
    h5_ = resume != nullptr
              ? FluidH5::reopen(s.out / kFluidH5, resume->files.h5_frames)
              : FluidH5::create(s.out / kFluidH5, h5Attributes(o, s, hamiltonian_.hbar()));
  }
}

void HistoryFiles::write(long k, double t, double h, const Eigen::MatrixXcd& Q, double drift) {
  probe_.evaluate(Q);
  const double energy = diagnostics_.energy(Q), enstrophy = diagnostics_.enstrophy(Q),
               commutator = diagnostics_.commutatorNorm(Q);
  csv_->write(t, energy, enstrophy, commutator, drift, h, probe_.residual());
  if (h5_) {
    // The frame's vorticity is the relative one, W = Q − F (Q itself on a resting sphere).
    const Eigen::MatrixXcd& W = hamiltonian_.relativeVorticity(Q, relative_);
    h5_->append({k, t, W, basis_.coefficients(W), energy, enstrophy, commutator, drift});
  }
}

HistoryFiles::Lengths HistoryFiles::sync() {
  Lengths lengths;
  lengths.history_bytes = csv_->sync();
  lengths.history_digest = csv_->digest();
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
  a.created = FluidH5::utcNow();
  return a;
}

void writeMatrixCsv(const std::filesystem::path& path, const Eigen::MatrixXcd& W) {
  app::AtomicFile file(path);
  app::CsvRow row(static_cast<std::size_t>(2 * W.cols()));
  for (Eigen::Index j = 0; j < W.rows(); ++j) {
    for (Eigen::Index k = 0; k < W.cols(); ++k) row.put(W(j, k).real());
    for (Eigen::Index k = 0; k < W.cols(); ++k) row.put(W(j, k).imag());
    row.writeTo(file);
  }
  file.commit();
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
