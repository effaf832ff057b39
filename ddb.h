// The public API of ddb in one include, but for the adaptive reference's class
// (<ddb/integrators/methods/reference.h>, which brings Boost.Odeint: makeMethod builds the
// reference without it on the library's groups). The per-concept headers below stay reachable
// on their own (<ddb/groups/so3.h>, ...); headers they include themselves (core/detail/: solver
// details, scalar helpers) are not listed.
#pragma once

#include <ddb/core/autodiff.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/dual_matrix.h>
#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lagrangian.h>
#include <ddb/core/legendre_hamiltonian.h>
#include <ddb/core/lie_group.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/retraction.h>
#include <ddb/core/solver_options.h>
#include <ddb/groups/cayley.h>
#include <ddb/groups/direct_product.h>
#include <ddb/groups/dual_number_sun.h>
#include <ddb/groups/exponential.h>
#include <ddb/groups/se2.h>
#include <ddb/groups/se3.h>
#include <ddb/groups/semidirect_product.h>
#include <ddb/groups/skew_hermitian_group.h>
#include <ddb/groups/so2.h>
#include <ddb/groups/so3.h>
#include <ddb/groups/son.h>
#include <ddb/groups/special_euclidean.h>
#include <ddb/groups/special_orthogonal.h>
#include <ddb/groups/sun.h>
#include <ddb/groups/swapped_parts_metric.h>
#include <ddb/integrators/drivers/flow_rate.h>
#include <ddb/integrators/drivers/integrate.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/matrix_kernels/matrix_cayley_transport.h>
#include <ddb/integrators/methods/composition.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/matrix_free_runge_kutta.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/one_step_method.h>
#include <ddb/integrators/methods/runge_kutta.h>
#include <ddb/integrators/methods/strang_splitting.h>
#include <ddb/integrators/methods/symmetric_ddb.h>
#include <ddb/integrators/solvers/matrix_legendre.h>
#include <ddb/systems/body_inertia.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/kirchhoff.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/planar_kirchhoff.h>
#include <ddb/systems/rigid_body.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <ddb/systems/zeitlin_spectra.h>
#include <ddb/systems/zeitlin_step_size.h>
#include <ddb/systems/zeitlin_viscosity.h>
