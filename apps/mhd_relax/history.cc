#include "mhd_relax/history.h"

#include <algorithm>
#include <cmath>

#include "common/cli.h"

namespace ddb::mhd {

namespace {

constexpr const char* kHistoryHeader =
    "t,h,kinetic_energy,magnetic_energy,energy,cross_helicity,residual,equilibrium_residual,"
    "invariant_drift\n";
constexpr int kHistoryColumns = 9;

/// The scale of a field: its spectral norm, or 1 for the zero field.
double scaleOf(const Eigen::MatrixXcd& field) {
  const double rho = SUN::spectralNorm(field);
  return rho > 0 ? rho : 1.0;
}

}  // namespace

InvariantDrift::InvariantDrift(const State& mu0) : first_(invariants(mu0)) {
  const double n = double(mu0.real.rows());
  const double theta = scaleOf(mu0.real), w = scaleOf(mu0.eps);
  for (int k = 2; k <= 4; ++k) scale_(k - 2) = n * std::pow(theta, k);
  for (int k = 1; k <= 3; ++k) scale_(k + 2) = n * w * std::pow(theta, k);
}

Eigen::Matrix<std::complex<double>, 6, 1> InvariantDrift::invariants(const State& mu) {
  const Eigen::MatrixXcd& Theta = mu.real;
  const Eigen::MatrixXcd& W = mu.eps;
  Eigen::Matrix<std::complex<double>, 6, 1> out;
  Eigen::MatrixXcd power = Theta;  // Θᵏ
  for (int k = 1; k <= 3; ++k) {
    // tr(WΘᵏ) = Σ W_ij (Θᵏ)_ji and tr Θᵏ⁺¹ = Σ Θ_ij (Θᵏ)_ji, without forming the products.
    out(k + 2) = W.cwiseProduct(power.transpose()).sum();
    out(k - 1) = Theta.cwiseProduct(power.transpose()).sum();
    if (k < 3) power = (power * Theta).eval();
  }
  return out;
}

double InvariantDrift::operator()(const State& mu) const {
  return ((invariants(mu) - first_).cwiseAbs().array() / scale_.array()).maxCoeff();
}

HistoryFiles::HistoryFiles(const Options& o, const Settings& s,
                           const LiePoissonSystem<DualNumberSUN>& system, const FileLengths* resume)
    : hamiltonian_(dynamic_cast<const ZeitlinMhdHamiltonian&>(system.hamiltonian())),
      diagnostics_(hamiltonian_),
      probe_(system),
      basis_(hamiltonian_.poisson()),
      drift_(zeitlinMhdState(s.W0, s.Theta0)),
      row_(kHistoryColumns) {
  const Eigen::Index n = s.W0.rows();
  if (resume != nullptr) {
    csv_.emplace(s.out / "history.csv", resume->history_bytes, resume->history_digest);
    h5_.emplace(s.out / "fluid.hdf5", n, hamiltonian_.hbar(), resume->frames);
  } else {
    csv_.emplace(s.out / "history.csv");
    csv_->write(kHistoryHeader);
    h5_.emplace(s.out / "fluid.hdf5",
                MhdH5Attributes{n, s.alpha, s.h, hamiltonian_.hbar(), o.method, s.init,
                                s.theta_init, app::projectVersion(), app::hdf5::utcNow()});
  }
}

void HistoryFiles::write(long k, double t, double h, const State& mu) {
  probe_.evaluate(mu);
  MhdFrameNumbers& n = last_;
  n.step = k;
  n.t = t;
  n.kinetic_energy = diagnostics_.kineticEnergy(mu);
  n.magnetic_energy = diagnostics_.magneticEnergy(mu);
  n.cross_helicity = diagnostics_.crossHelicity(mu);
  n.residual = probe_.residual();
  n.equilibrium_residual = diagnostics_.equilibriumResidual(mu);
  n.invariant_drift = drift_(mu);
  for (const double v :
       {t, h, n.kinetic_energy, n.magnetic_energy, n.kinetic_energy + n.magnetic_energy,
        n.cross_helicity, n.residual, n.equilibrium_residual, n.invariant_drift}) {
    row_.put(v);
  }
  row_.writeTo(*csv_);
  h5_->append(basis_.coefficients(mu.eps), basis_.coefficients(mu.real), n);
}

FileLengths HistoryFiles::sync() {
  h5_->flush();
  const std::uint64_t bytes = csv_->sync();
  return {bytes, csv_->digest(), h5_->frames()};
}

void HistoryFiles::commit() {
  csv_->commit();
  h5_->commit();
}

}  // namespace ddb::mhd
