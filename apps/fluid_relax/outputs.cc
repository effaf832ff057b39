#include "fluid_relax/outputs.h"

#include "common/cli.h"

namespace ddb::fluid {

HistoryCsv::HistoryCsv(const std::filesystem::path& path) : file_(path), row_(7) {
  file_.write("t,energy,enstrophy,commutator_norm,spectrum_drift,h,residual\n");
}

HistoryCsv::HistoryCsv(const std::filesystem::path& path, std::uint64_t length)
    : file_(path, length), row_(7) {}

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
