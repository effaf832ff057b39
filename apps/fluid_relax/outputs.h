// fluid-relax's matrix and coefficient files (docs/file-formats.md, "fluid-relax"):
// W_final.csv in the layout of --init-file, omega_initial.csv and omega_final.csv.
#pragma once

#include <ddb/systems/spherical_harmonic_basis.h>

#include <Eigen/Core>
#include <filesystem>

namespace ddb::fluid {

/// W in the layout of --init-file: row j is Re W[j, :] then Im W[j, :].
void writeMatrixCsv(const std::filesystem::path& path, const Eigen::MatrixXcd& W);

/// The real spherical-harmonic coefficients ω_lm of W (docs/conventions.md §2), one row
/// "l,m,omega" each, for the figures.
void writeOmegaCsv(const std::filesystem::path& path, const SphericalHarmonicBasis& basis,
                   const Eigen::MatrixXcd& W);

}  // namespace ddb::fluid
