// ddb-compare's problems on matrix groups (docs/reference/command-lines-and-files.md,
// "ddb-compare"): the SO(N) generalised rigid body (Manakov) and Zeitlin's SU(N) fluid
// (docs/reference/conventions.md §2), with the app's defaults and the largest N its reference can
// follow.
#pragma once

#include <ddb/groups/son.h>
#include <ddb/groups/sun.h>

#include <CLI/CLI.hpp>
#include <Eigen/Core>

#include "ddb_compare/options.h"
#include "ddb_compare/problems.h"

namespace ddb::compare {

/// The largest N of the matrix systems: the reference (adaptive RKF 7(8) at tolerance
/// 1e-13) costs O(N³) per evaluation of the field over thousands of steps, and every
/// state's spectrum is computed for casimir_drift; docs/reference/command-lines-and-files.md gives
/// the times measured that set it.
constexpr Eigen::Index kMaxMatrixN = 64;

/// Defaults (docs/reference/command-lines-and-files.md): N, the horizon, α.
constexpr long kManakovDefaultN = 5;
constexpr long kZeitlinDefaultN = 16;
constexpr double kMatrixDefaultTEnd = 10.0;
constexpr double kMatrixDefaultAlpha = 0.5;

/// The Manakov body's default principal values J_i = 1 + (i − 1)/(N − 1), i = 1..N:
/// distinct, from 1 to 2, so that no two axes are alike.
Eigen::VectorXd defaultManakovJ(Eigen::Index n);

/// The seeded initial momentum of the Manakov body: the real part of the fluid's seeded
/// random vorticity (randomVorticity, zeitlin_initial_conditions.h), a real skew matrix
/// with i.i.d. normal entries above the diagonal, scaled to ‖M₀‖_F = √N.
Eigen::MatrixXd seededManakovMomentum(Eigen::Index n, std::uint64_t seed);

/// --system manakov: --n, --j, --alpha, --mu0-file or --seed.
Problem<SON> manakovProblem(const CLI::App& cli, const Options& o);

/// --system zeitlin: --n, --alpha, --init and --seed, or --init-file.
Problem<SUN> zeitlinProblem(const CLI::App& cli, const Options& o);

}  // namespace ddb::compare
