// Counts the mallocs (and callocs and reallocs) of the program the counter is linked into:
// Eigen takes a dynamic matrix's storage from malloc, and operator new ends in malloc, so one
// count sees both (a count of operator new alone misses every Eigen matrix). Link the object
// library ddb_malloc_counter into a test or benchmark binary, never into the library.
#pragma once

namespace ddb::tools {

/// The number of malloc, calloc and realloc calls so far in this process.
long mallocCount();

}  // namespace ddb::tools
