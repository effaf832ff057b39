// The generic system's virtual functions compiled once for the group of each system the library
// ships (core/lie_poisson_system.h, DDB_LIE_POISSON_SYSTEM_INSTANCE). The systems' headers, which
// declare them `extern`, come first: a declaration after the definition is an error.
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/kirchhoff.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/planar_kirchhoff.h>
#include <ddb/systems/rigid_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_mhd.h>

DDB_LIE_POISSON_SYSTEM_INSTANCE(, ::ddb::SO3);
DDB_LIE_POISSON_SYSTEM_INSTANCE(, ::ddb::SE2);
DDB_LIE_POISSON_SYSTEM_INSTANCE(, ::ddb::SE3);
DDB_LIE_POISSON_SYSTEM_INSTANCE(, ::ddb::SON);
DDB_LIE_POISSON_SYSTEM_INSTANCE(, ::ddb::SUN);
DDB_LIE_POISSON_SYSTEM_INSTANCE(, ::ddb::DualNumberSUN);
