# The distributed layer (docs/design/distributed.md): matrices distributed block-cyclically over
# MPI ranks with ScaLAPACK, built when MPI and Debian's ScaLAPACK for Open MPI are found; the
# target ddb::distributed (a static library: the method table for its groups compiled once,
# distributed/distributed_method_table.h) and the package's component `distributed`, in an
# export set of its own so that a plain find_package(ddb) never looks for MPI
# (cmake/DdbBackend.cmake).
option(DDB_BUILD_MPI "Build the distributed layer and its tests when MPI and ScaLAPACK are found"
       ${PROJECT_IS_TOP_LEVEL})
ddb_declare_backend(distributed TITLE "distributed layer" WITHOUT
  "this ddb was installed without its distributed layer: configure ddb with DDB_BUILD_MPI ON where MPI and ScaLAPACK are found (Debian: libopenmpi-dev, libscalapack-openmpi-dev) and install it again")
if(DDB_BUILD_MPI)
  enable_language(C)
  find_package(MPI COMPONENTS C QUIET)
  find_library(DDB_SCALAPACK_LIBRARY NAMES scalapack-openmpi)
  if(MPI_C_FOUND AND DDB_SCALAPACK_LIBRARY)
    # Installed: the consumer's package config finds MPI and ScaLAPACK again (ddb::scalapack,
    # distributed/component.cmake.in). The C API only: Open MPI's mpi.h otherwise pulls in its
    # C++ bindings in C++ sources.
    ddb_add_backend(distributed
      SOURCES ${CMAKE_CURRENT_LIST_DIR}/distributed_method_table.cc
      LINK MPI::MPI_C $<BUILD_INTERFACE:${DDB_SCALAPACK_LIBRARY}> $<INSTALL_INTERFACE:ddb::scalapack>
      DEFINITIONS OMPI_SKIP_MPICXX MPICH_SKIP_MPICXX
      TESTS mpi/tests.cmake)
    message(STATUS "The distributed layer is built (MPI ${MPI_C_VERSION}, ${DDB_SCALAPACK_LIBRARY})")
  else()
    message(STATUS "The distributed layer is not built: it needs MPI and ScaLAPACK (Debian: "
                   "libopenmpi-dev, openmpi-bin, libscalapack-openmpi-dev)")
  endif()
else()
  message(STATUS "The distributed layer is not built (DDB_BUILD_MPI is OFF)")
endif()
