# Fails if a formula reaches past the matrix backend to the storage of a matrix
# (docs/design/matrix-backend.md): outside the backends, no file of the library's formula layers
# (core, groups, systems, integrators) nor of the apps names a backend's local array
# (`.local()`, `entries(`), so that a backend whose memory is not this process's (a GPU,
# MPI ranks) runs every formula unchanged.
#   cmake -DSOURCE_DIR=<tree> -P tests/checks/check_backend_seam.cmake
cmake_policy(SET CMP0009 NEW)
if(NOT IS_DIRECTORY "${SOURCE_DIR}")
  message(FATAL_ERROR "set SOURCE_DIR to the ddb source tree")
endif()

set(globs)
foreach(folder core groups systems integrators apps)
  list(APPEND globs "${SOURCE_DIR}/${folder}/*.h" "${SOURCE_DIR}/${folder}/*.cc")
endforeach()
file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" ${globs})
# The backends themselves: the dense one and its element-wise passes.
list(REMOVE_ITEM files core/matrix_backend.h core/parallel_passes.h)

set(errors "")
foreach(file IN LISTS files)
  file(STRINGS "${SOURCE_DIR}/${file}" lines REGEX "(\\.local\\(\\))|([^A-Za-z_]entries\\()")
  foreach(line IN LISTS lines)
    string(STRIP "${line}" line)
    string(APPEND errors "  ${file}: ${line}\n")
  endforeach()
endforeach()

list(LENGTH files count)
if(count LESS 40)
  message(FATAL_ERROR "found only ${count} files under ${SOURCE_DIR}")
endif()
if(errors)
  message(FATAL_ERROR "formulas that touch a matrix's storage instead of calling the backend "
                      "(docs/design/matrix-backend.md):\n${errors}")
endif()
message(STATUS "${count} files of core, groups, systems, integrators and apps go through the "
               "matrix backend")
