# An install of a tree configured but not built installs nothing and says to build first (the
# library has a compiled part since 0.3.0); with the library built but not the compiled backends
# (cmake --build --target ddb, where CUDA's toolkit or MPI is found), the install skips each
# backend's library with a message and the package refuses its component, saying why
# (CMakeLists.txt; docs/guide/getting-started.md). Run by ctest as
#   cmake -DSOURCE_DIR=<tree> -DWORK_DIR=<scratch> -DBUILT_LIBRARY=<libddb.a> -P
#         check_configure_only_install.cmake
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
                        -DDDB_BUILD_TESTS=OFF
                RESULT_VARIABLE configured OUTPUT_VARIABLE configure_log ERROR_VARIABLE configure_log)
if(NOT configured EQUAL 0)
  message(FATAL_ERROR "the configure failed:\n${configure_log}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --install ${WORK_DIR}/build --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE installed OUTPUT_VARIABLE install_log ERROR_VARIABLE install_log)
string(FIND "${install_log}" "libddb.a was not built: run cmake --build" told)
if(installed EQUAL 0 OR told EQUAL -1 OR EXISTS ${WORK_DIR}/prefix)
  message(FATAL_ERROR "a configure-only install must fail, saying why, and install nothing:\n"
                      "${install_log}")
endif()
# The compiled backends this configure builds: each line is the backend's message at configure,
# its library's file and what the package says when the component is asked for without it.
set(backends "")
foreach(backend "The CUDA backend is built|libddb_cuda.a|cuda|installed before its CUDA backend"
                "The distributed layer is built|libddb_distributed.a|distributed|installed before its distributed layer")
  string(REPLACE "|" ";" fields "${backend}")
  list(GET fields 0 configured_text)
  string(FIND "${configure_log}" "${configured_text}" found)
  if(NOT found EQUAL -1)
    list(APPEND backends "${backend}")
  endif()
endforeach()
if(backends)
  # The library built and the backends not: the library is this build's (BUILT_LIBRARY), copied
  # where the scratch tree builds it. What is checked is the install and the package, not the
  # library's code, and building it again took about 200 s of this check on 2 cores (165 s at -O0).
  get_filename_component(library_name ${BUILT_LIBRARY} NAME)
  file(COPY_FILE ${BUILT_LIBRARY} ${WORK_DIR}/build/${library_name})
  execute_process(COMMAND ${CMAKE_COMMAND} --install ${WORK_DIR}/build --prefix ${WORK_DIR}/prefix
                  RESULT_VARIABLE installed OUTPUT_VARIABLE install_log ERROR_VARIABLE install_log)
  if(NOT installed EQUAL 0 OR NOT EXISTS ${WORK_DIR}/prefix/include/ddb/ddb.h OR
     NOT EXISTS ${WORK_DIR}/prefix/share/ddb/cmake/ddbConfig.cmake)
    message(FATAL_ERROR "the install of the built library failed or lacks its files:\n"
                        "${install_log}")
  endif()
  foreach(backend IN LISTS backends)
    string(REPLACE "|" ";" fields "${backend}")
    list(GET fields 1 backend_library)
    list(GET fields 2 component)
    list(GET fields 3 refusal)
    string(FIND "${install_log}" "Skipping ${backend_library}: it was not built" skipped)
    if(skipped EQUAL -1)
      message(FATAL_ERROR "the install does not say that it skipped ${backend_library}:\n"
                          "${install_log}")
    endif()
    # A consumer asking for the component is told why it cannot have it; a plain one is served.
    # (The distributed component finds MPI with the C compiler.)
    set(consumer ${WORK_DIR}/consumer_${component})
    file(WRITE ${consumer}/CMakeLists.txt
         "cmake_minimum_required(VERSION 3.20)\nproject(consumer LANGUAGES C CXX)\n"
         "find_package(ddb REQUIRED)\nmessage(STATUS \"plain ddb found\")\n"
         "find_package(ddb REQUIRED COMPONENTS ${component})\n")
    execute_process(COMMAND ${CMAKE_COMMAND} -S ${consumer} -B ${consumer}/build
                            -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix
                    RESULT_VARIABLE consumed OUTPUT_VARIABLE consumer_log ERROR_VARIABLE consumer_log)
    # The refusal must be for the missing library, not for some other reason.
    string(FIND "${consumer_log}" "plain ddb found" served)
    string(FIND "${consumer_log}" "${refusal}" refused)
    if(consumed EQUAL 0 OR served EQUAL -1 OR refused EQUAL -1)
      message(FATAL_ERROR "a consumer of the component ${component} of the configure-only "
                          "install:\n${consumer_log}")
    endif()
    message(STATUS "The install skipped the unbuilt ${backend_library}, saying so, and the "
                   "package's component ${component} is not found")
  endforeach()
else()
  message(STATUS "No compiled backend is configured here: only the configure-only install is "
                 "checked")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
