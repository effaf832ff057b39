// Counts the bytes this rank sends to other ranks by intercepting the MPI calls below (the
// MPI profiling interface: each definition here counts, then calls PMPI_...); a call not
// among them (MPI_Gather, MPI_Scatter, MPI_Alltoall, non-blocking collectives) would not
// be counted. Linked
// into distributed-step-bench only, where it sees the calls of the library, of BLACS and of
// ScaLAPACK alike. What is counted is the payload each call states: point-to-point sends
// (blocking, non-blocking, persistent at MPI_Start, the send half of MPI_Sendrecv), and
// for collectives the data this rank contributes for the other ranks (Alltoallv: its
// counts to the others; Allgather: its block times P − 1; Bcast at the root: the buffer
// times P − 1; Allreduce and Reduce: its buffer once). A collective's algorithm may forward
// more than that (tree hops); MPI_Send_init records the size its starts count.
#include "mpi_byte_counter.h"

#include <mpi.h>

#include <map>

namespace {

std::int64_t sent = 0;
std::map<MPI_Request, std::int64_t> persistent;  // a persistent send's bytes per start

std::int64_t bytes(int count, MPI_Datatype type) {
  int size = 0;
  PMPI_Type_size(type, &size);
  return static_cast<std::int64_t>(count) * size;
}
int others(MPI_Comm comm) {
  int size = 1;
  PMPI_Comm_size(comm, &size);
  return size - 1;
}

}  // namespace

namespace ddb::bench {
std::int64_t mpiBytesSent() { return sent; }
}  // namespace ddb::bench

extern "C" {

int MPI_Send(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm) {
  sent += bytes(count, type);
  return PMPI_Send(buf, count, type, dest, tag, comm);
}
int MPI_Ssend(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm) {
  sent += bytes(count, type);
  return PMPI_Ssend(buf, count, type, dest, tag, comm);
}
int MPI_Rsend(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm) {
  sent += bytes(count, type);
  return PMPI_Rsend(buf, count, type, dest, tag, comm);
}
int MPI_Bsend(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm) {
  sent += bytes(count, type);
  return PMPI_Bsend(buf, count, type, dest, tag, comm);
}
int MPI_Isend(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm,
              MPI_Request* request) {
  sent += bytes(count, type);
  return PMPI_Isend(buf, count, type, dest, tag, comm, request);
}
int MPI_Issend(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm,
               MPI_Request* request) {
  sent += bytes(count, type);
  return PMPI_Issend(buf, count, type, dest, tag, comm, request);
}
int MPI_Send_init(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm,
                  MPI_Request* request) {
  const int status = PMPI_Send_init(buf, count, type, dest, tag, comm, request);
  persistent[*request] = bytes(count, type);
  return status;
}
int MPI_Start(MPI_Request* request) {
  if (const auto it = persistent.find(*request); it != persistent.end()) sent += it->second;
  return PMPI_Start(request);
}
int MPI_Startall(int count, MPI_Request requests[]) {
  for (int i = 0; i < count; ++i) {
    if (const auto it = persistent.find(requests[i]); it != persistent.end()) sent += it->second;
  }
  return PMPI_Startall(count, requests);
}
int MPI_Request_free(MPI_Request* request) {
  persistent.erase(*request);
  return PMPI_Request_free(request);
}
int MPI_Sendrecv(const void* sendbuf, int sendcount, MPI_Datatype sendtype, int dest, int sendtag,
                 void* recvbuf, int recvcount, MPI_Datatype recvtype, int source, int recvtag,
                 MPI_Comm comm, MPI_Status* status) {
  sent += bytes(sendcount, sendtype);
  return PMPI_Sendrecv(sendbuf, sendcount, sendtype, dest, sendtag, recvbuf, recvcount, recvtype,
                       source, recvtag, comm, status);
}
int MPI_Alltoallv(const void* sendbuf, const int sendcounts[], const int sdispls[],
                  MPI_Datatype sendtype, void* recvbuf, const int recvcounts[], const int rdispls[],
                  MPI_Datatype recvtype, MPI_Comm comm) {
  int rank = 0;
  PMPI_Comm_rank(comm, &rank);
  for (int r = 0; r <= others(comm); ++r) {
    if (r != rank) sent += bytes(sendcounts[r], sendtype);
  }
  return PMPI_Alltoallv(sendbuf, sendcounts, sdispls, sendtype, recvbuf, recvcounts, rdispls,
                        recvtype, comm);
}
int MPI_Allgather(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf,
                  int recvcount, MPI_Datatype recvtype, MPI_Comm comm) {
  sent += bytes(sendcount, sendtype) * others(comm);
  return PMPI_Allgather(sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, comm);
}
int MPI_Allreduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype type, MPI_Op op,
                  MPI_Comm comm) {
  if (others(comm) > 0) sent += bytes(count, type);
  return PMPI_Allreduce(sendbuf, recvbuf, count, type, op, comm);
}
int MPI_Reduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype type, MPI_Op op,
               int root, MPI_Comm comm) {
  int rank = 0;
  PMPI_Comm_rank(comm, &rank);
  if (rank != root) sent += bytes(count, type);
  return PMPI_Reduce(sendbuf, recvbuf, count, type, op, root, comm);
}
int MPI_Bcast(void* buffer, int count, MPI_Datatype type, int root, MPI_Comm comm) {
  int rank = 0;
  PMPI_Comm_rank(comm, &rank);
  if (rank == root) sent += bytes(count, type) * others(comm);
  return PMPI_Bcast(buffer, count, type, root, comm);
}

}  // extern "C"
