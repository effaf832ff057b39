// The forcing of Zeitlin's fluid (systems/zeitlin_forcing.h), compiled once.
#include <ddb/core/errors.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_forcing.h>
#include <ddb/systems/zeitlin_spectra.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <utility>

namespace ddb {

ZeitlinForcingBand::ZeitlinForcingBand(Eigen::Index n, const ZeitlinStochasticForcing& forcing,
                                       double kappa_squared)
    : forcing_(forcing) {
  forcing.validate(n);
  const SphericalHarmonicBasis basis{HoppeYauLaplacian(n)};
  const int low = forcing.band_centre - forcing.band_half_width;
  const int high = forcing.band_centre + forcing.band_half_width;
  // The energy of unit coefficients on the band, through the spectra's formula.
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n * n);
  for (int l = low; l <= high; ++l) {
    for (int m = -l; m <= l; ++m) {
      unit(SphericalHarmonicBasis::index(l, m)) = 1.0;
      const Eigen::MatrixXcd T = basis.element(l, m);
      const Eigen::Index d = std::abs(m);
      modes_.push_back({d, T.diagonal(d), T.diagonal(-d)});
    }
  }
  const double unit_energy = zeitlinSpectra(unit, kappa_squared).energy.sum();
  sigma_ = std::sqrt(forcing.rate / unit_energy);
}

void ZeitlinForcingBand::coefficients(double h, std::uint64_t draw, Eigen::VectorXd& c) const {
  const double scale = sigma_ * std::sqrt(h);
  for (std::size_t j = 0; j < modes_.size(); ++j) {
    c(Eigen::Index(j)) = scale * counterNormal(forcing_.seed, draw, j);
  }
}

void ZeitlinStochasticForcingFlow::advance(Eigen::MatrixXcd& W, double h) {
  const Eigen::VectorXd& c = nextKick(h);
  const auto& modes = band().modes();
  for (std::size_t j = 0; j < modes.size(); ++j) {
    const ZeitlinForcingBand::Mode& mode = modes[j];
    W.diagonal(mode.offset) += c(Eigen::Index(j)) * mode.upper;
    if (mode.offset != 0) W.diagonal(-mode.offset) += c(Eigen::Index(j)) * mode.lower;
  }
}

ZeitlinFixedForcingFlow::ZeitlinFixedForcingFlow(Eigen::Index n, Eigen::MatrixXcd forcing)
    : forcing_(std::move(forcing)) {
  requireValid(n, forcing_);
}

void ZeitlinFixedForcingFlow::requireValid(Eigen::Index n, const Eigen::MatrixXcd& forcing) {
  if (forcing.rows() != n || forcing.cols() != n) {
    throwInvalid("forcing", std::to_string(forcing.rows()) + "x" + std::to_string(forcing.cols()),
                 "must be N x N, N = " + std::to_string(n));
  }
  if (!forcing.allFinite()) throwInvalid("forcing", "a matrix", "must be finite");
  const double tolerance = 1e-12 * std::max(1.0, forcing.norm());
  if ((forcing + forcing.adjoint()).norm() > tolerance || std::abs(forcing.trace()) > tolerance) {
    throwInvalid("forcing", "a matrix", "must be traceless and skew-Hermitian (in su(N))");
  }
}

}  // namespace ddb
