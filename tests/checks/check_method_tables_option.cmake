# A name in DDB_METHOD_TABLES that is not one of the library's method tables (a group's name
# in the wrong case, a typo) stops the configure at once, naming the option and the name, and
# writes no build system (CMakeLists.txt). Run by ctest as
#   cmake -DSOURCE_DIR=<tree> -DWORK_DIR=<scratch> -P check_method_tables_option.cmake
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}
                        "-DDDB_METHOD_TABLES=so3;SE2"
                RESULT_VARIABLE configured OUTPUT_VARIABLE log ERROR_VARIABLE log)
string(FIND "${log}" "DDB_METHOD_TABLES: 'SE2' is not a method table" named)
string(FIND "${log}" "Eigen3" reached_packages)
if(configured EQUAL 0 OR named EQUAL -1 OR NOT reached_packages EQUAL -1 OR
   EXISTS ${WORK_DIR}/Makefile)
  message(FATAL_ERROR "a configure with DDB_METHOD_TABLES=so3;SE2 must stop before looking for "
                      "packages, naming the option and 'SE2', and write no build system:\n${log}")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
