#include "fluid_relax/outputs.h"

#include "common/atomic_file.h"
#include "common/csv_row.h"

namespace ddb::fluid {

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
