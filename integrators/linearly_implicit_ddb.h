// Deprecated: this header moved to
// <ddb/integrators/methods/linearly_implicit_ddb.h>
// in 0.2.0, and this path goes in 0.3.0 (CHANGELOG.md, "Deprecated"; CONTRIBUTING.md,
// "Public names"). It includes the new one.
#pragma once

#ifndef DDB_NO_DEPRECATED_HEADER_WARNINGS
#pragma GCC warning \
    "deprecated (CHANGELOG.md): include <ddb/integrators/methods/linearly_implicit_ddb.h>"
#endif
#include <ddb/integrators/methods/linearly_implicit_ddb.h>
