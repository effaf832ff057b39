// The bytes this rank has sent to other ranks since the start, counted at the MPI calls
// (bench/mpi_byte_counter.cc, which intercepts them through the MPI profiling interface).
#pragma once

#include <cstdint>

namespace ddb::bench {

std::int64_t mpiBytesSent();

}  // namespace ddb::bench
