# Included by tests/CMakeLists.txt, in its scope, where the distributed layer is built
# (distributed/backend.cmake).
# Every public name of the layer, compiled (as public_names, tests/CMakeLists.txt).
add_library(public_names_distributed OBJECT api/public_names_distributed.cc)
target_link_libraries(public_names_distributed PRIVATE ddb_distributed ddb_warnings)
target_compile_options(public_names_distributed PRIVATE -O0)
# The distributed layer's tests (docs/design/distributed.md), each run on 1, 2, 3 and 4 ranks,
# oversubscribed (the machine may have fewer cores), one BLAS thread per rank; Open MPI
# refuses to run as root unless told (containers, CI). Oversubscribed ranks that spin while
# they wait starve each other (on 2 busy cores one run on 3 ranks took over 60 s, alone
# 4 s): the ranks yield when idle and no other test runs beside them (RUN_SERIAL). The
# sanitizer build (scripts/test.sh) builds only its one program, so it turns DDB_BUILD_MPI
# off rather than list these unbuilt. No grace period (odls_base_sigkill_timeout, 1 s by default)
# before mpiexec kills the other ranks of a job in which one exited with a status other than 0:
# every rank of fluid-relax-mpi exits only after MPI_Finalize, so none is ever killed with its
# files unwritten, and the grace period made each run that exits 1 or 2 take 1-2 s more
# (docs/results/compile-costs.md, "The tests' time"). Open MPI's own point-to-point layer (pml
# ob1, shared memory between the ranks of one machine): by default every rank probes UCX and OFI
# for a network first, 0.2 s of every start (an empty program on 2 ranks: 0.42 s, with ob1
# 0.21 s), and test_fluid_relax_mpi starts mpiexec 97 times (79 s against 58 s). The
# test programs that start mpiexec themselves get the same list (DDB_MPI_TEST_ENVIRONMENT,
# tests/support/app_test_support.h).
set(ddb_mpi_test_env "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1;OMPI_MCA_mpi_yield_when_idle=1;OMPI_MCA_odls_base_sigkill_timeout=0;OMPI_MCA_pml=ob1;OPENBLAS_NUM_THREADS=1")
# The same list as one word per variable: a list's semicolons would split a definition.
string(JOIN " " ddb_mpi_test_env_words ${ddb_mpi_test_env})
add_library(ddb_mpi_test_main OBJECT support/mpi_test_main.cc)
target_include_directories(ddb_mpi_test_main PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/support)
target_link_libraries(ddb_mpi_test_main PUBLIC ddb_distributed GTest::gtest PRIVATE ddb_warnings)
# One program, its six files compiled as one translation unit (as ddb_test_program's).
add_executable(mpi_distributed mpi/test_distributed_matrix.cc mpi/test_distributed_eigenbasis.cc
                               mpi/test_distributed_poisson.cc mpi/test_distributed_ddb.cc
                               mpi/test_distributed_exact_flows.cc mpi/test_distributed_mhd.cc)
set_target_properties(mpi_distributed PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
target_link_libraries(mpi_distributed PRIVATE ddb_distributed ddb_warnings ddb_mpi_test_main)
foreach(ranks 1 2 3 4)
  add_test(NAME mpi_distributed_np${ranks}
           COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${ranks} ${MPIEXEC_PREFLAGS}
                   $<TARGET_FILE:mpi_distributed> ${MPIEXEC_POSTFLAGS})
  set_tests_properties(mpi_distributed_np${ranks} PROPERTIES TIMEOUT 300 PROCESSORS ${ranks}
    RUN_SERIAL TRUE ENVIRONMENT "${ddb_mpi_test_env}")
endforeach()
# P = 2 and 3 again on the other shape, one row of ranks (the default has one column).
foreach(ranks 2 3)
  add_test(NAME mpi_distributed_np${ranks}_one_row
           COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${ranks} ${MPIEXEC_PREFLAGS}
                   $<TARGET_FILE:mpi_distributed> ${MPIEXEC_POSTFLAGS} --grid-rows=1)
  set_tests_properties(mpi_distributed_np${ranks}_one_row PROPERTIES TIMEOUT 300 PROCESSORS ${ranks}
    RUN_SERIAL TRUE ENVIRONMENT "${ddb_mpi_test_env}")
endforeach()
# fluid-relax-mpi against fluid-relax (it starts mpiexec itself, 1–4 ranks).
if(DDB_BUILD_APPS)
  add_executable(test_fluid_relax_mpi mpi/test_fluid_relax_mpi.cc)
  target_include_directories(test_fluid_relax_mpi PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/support)
  # ddb::ddb for the method table (the methods the app offers).
  target_link_libraries(test_fluid_relax_mpi PRIVATE GTest::gtest_main nlohmann_json::nlohmann_json
                                                     ddb::ddb HDF5::HDF5 ddb_warnings)
  target_compile_definitions(test_fluid_relax_mpi PRIVATE
    FLUID_RELAX_PATH="$<TARGET_FILE:fluid-relax>"
    FLUID_RELAX_MPI_PATH="$<TARGET_FILE:fluid-relax-mpi>"
    MPIEXEC_PATH="${MPIEXEC_EXECUTABLE}" DDB_MPI_TEST_ENVIRONMENT="${ddb_mpi_test_env_words}")
  add_dependencies(test_fluid_relax_mpi fluid-relax fluid-relax-mpi)
  # The I/O faults of fluid-relax-mpi, under mpiexec (tests/apps/test_io_faults.cc).
  target_compile_definitions(apps_fluid_relax PRIVATE
    FLUID_RELAX_MPI_PATH="$<TARGET_FILE:fluid-relax-mpi>" MPIEXEC_PATH="${MPIEXEC_EXECUTABLE}"
    DDB_MPI_TEST_ENVIRONMENT="${ddb_mpi_test_env_words}")
  add_dependencies(apps_fluid_relax fluid-relax-mpi)
  gtest_discover_tests(test_fluid_relax_mpi DISCOVERY_TIMEOUT 60 NO_PRETTY_VALUES
                       PROPERTIES TIMEOUT 300 PROCESSORS 2 RUN_SERIAL TRUE)
endif()
