# An install of a tree configured but not built installs nothing and says to build first (the
# library has a compiled part since 0.3.0); with the library built but not the CUDA backend
# (cmake --build --target ddb, where CUDA's toolkit is found), the install skips the backend
# with a message and the package refuses its component, saying why (CMakeLists.txt;
# docs/guide/getting-started.md). Run by ctest as
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
string(FIND "${configure_log}" "The CUDA backend is built" cuda_configured)
if(NOT cuda_configured EQUAL -1)
  # The library built and the backend not: the library is this build's (BUILT_LIBRARY), copied
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
  string(FIND "${install_log}" "Skipping libddb_cuda.a: it was not built" skipped)
  if(skipped EQUAL -1)
    message(FATAL_ERROR "the install does not say that it skipped the CUDA library:\n${install_log}")
  endif()
  # A consumer asking for the component is told why it cannot have it; a plain one is served.
  file(WRITE ${WORK_DIR}/consumer/CMakeLists.txt
       "cmake_minimum_required(VERSION 3.20)\nproject(consumer LANGUAGES CXX)\n"
       "find_package(ddb REQUIRED)\nmessage(STATUS \"plain ddb found\")\n"
       "find_package(ddb REQUIRED COMPONENTS cuda)\n")
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK_DIR}/consumer -B ${WORK_DIR}/consumer/build
                          -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix
                  RESULT_VARIABLE consumed OUTPUT_VARIABLE consumer_log ERROR_VARIABLE consumer_log)
  # The refusal must be for the missing library, not for some other reason.
  string(FIND "${consumer_log}" "plain ddb found" served)
  string(FIND "${consumer_log}" "installed before its CUDA backend" refused)
  if(consumed EQUAL 0 OR served EQUAL -1 OR refused EQUAL -1)
    message(FATAL_ERROR "a consumer of the configure-only install:\n${consumer_log}")
  endif()
  message(STATUS "CUDA's toolkit is found: the install skipped the unbuilt backend, saying so, "
                 "and the package's component cuda is not found")
else()
  message(STATUS "CUDA's toolkit is not found here: only the configure-only install is checked")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
