// makeMethod for SE(3) composed, SemidirectProduct<SO3>, compiled once into the library
// (integrators/methods/method_table.h, its end): the tests, ddb-bench and a user's program on it
// build none of its methods.
#include <ddb/groups/se3.h>
#include <ddb/groups/semidirect_product.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>

DDB_METHOD_TABLE_INSTANCE(, ::ddb::detail::SE3Composed);
