# Fails if any file includes one of the library's headers by a path that resolves only
# inside this tree (docs/design/architecture.md, "Layout"). The library folders sit at the top of
# the tree but are installed under include/ddb/, so the one spelling that works in the tree, through
# add_subdirectory and after find_package alike is <ddb/...>; <core/x.h>, "groups/x.h" or
# include/ddb/... would resolve here only if the source root were on the include path.
# Every <ddb/...> path must also name a header that exists, so a stale path fails too.
#   cmake -DSOURCE_DIR=<tree> -P tests/checks/check_includes.cmake
cmake_policy(SET CMP0009 NEW)  # globs do not follow links (the build tree has some)
if(NOT IS_DIRECTORY "${SOURCE_DIR}")
  message(FATAL_ERROR "set SOURCE_DIR to the ddb source tree")
endif()

# The backends are the folders with a backend.cmake (cmake/DdbBackend.cmake), built here or not.
file(GLOB backend_files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/*/backend.cmake")
set(backends)
foreach(backend_file IN LISTS backend_files)
  get_filename_component(backend "${backend_file}" DIRECTORY)
  list(APPEND backends ${backend})
endforeach()
set(installed_parts core groups systems integrators ${backends})
set(parts ${installed_parts} instantiations)
list(JOIN parts "|" parts_pattern)
list(JOIN installed_parts "|" installed_pattern)
set(library_globs ddb.h)
foreach(part IN LISTS parts)
  list(APPEND library_globs ${part}/*.h)
endforeach()
list(TRANSFORM library_globs PREPEND "${SOURCE_DIR}/")
file(GLOB_RECURSE library_files RELATIVE "${SOURCE_DIR}" ${library_globs})
set(user_globs)
foreach(folder apps bench examples python tests tools)
  list(APPEND user_globs "${SOURCE_DIR}/${folder}/*.h" "${SOURCE_DIR}/${folder}/*.cc")
endforeach()
# The library's and the backends' compiled sources include the headers as the other sources do.
foreach(part IN LISTS parts)
  list(APPEND user_globs "${SOURCE_DIR}/${part}/*.cc" "${SOURCE_DIR}/${part}/*.cu")
endforeach()
file(GLOB_RECURSE user_files RELATIVE "${SOURCE_DIR}" ${user_globs})

set(errors "")
foreach(file IN LISTS library_files user_files)
  # #include lines and __has_include tests, with <...> or "..." paths.
  file(STRINGS "${SOURCE_DIR}/${file}" lines
       REGEX "(^[ \t]*#[ \t]*include[ \t]*[<\"])|(__has_include[ \t]*\\([ \t]*[<\"])")
  list(FIND library_files "${file}" in_library)
  get_filename_component(folder "${SOURCE_DIR}/${file}" DIRECTORY)
  foreach(line IN LISTS lines)
    string(REGEX MATCH "[<\"]([^>\"]+)[>\"]" _ "${line}")
    set(path "${CMAKE_MATCH_1}")
    if(path MATCHES "^(${parts_pattern}|include)/" OR path STREQUAL "ddb.h")
      string(APPEND errors "  ${file}: ${line}  (resolves only in the tree; write <ddb/...>)\n")
    elseif(path MATCHES "^ddb/(.*)$")
      # Installed, include/ddb/ holds the four folders, ddb.h and, when they are built, the
      # backends' folders (the distributed layer's distributed/, docs/design/distributed.md, and
      # the CUDA backend's cuda/, docs/guide/gpu.md); nothing else of the tree.
      set(rest "${CMAKE_MATCH_1}")
      if(NOT rest MATCHES "^(${installed_pattern})/" AND NOT rest STREQUAL "ddb.h")
        string(APPEND errors "  ${file}: ${line}  (not a library header: <ddb/${installed_pattern}"
                             "/...> or <ddb/ddb.h>)\n")
      elseif(NOT EXISTS "${SOURCE_DIR}/${rest}")
        string(APPEND errors "  ${file}: ${line}  (no such header in the library)\n")
      endif()
    elseif(line MATCHES "\"")
      if(in_library GREATER -1)
        # A quoted include in an installed header would search the header's own folder.
        string(APPEND errors "  ${file}: ${line}  (library headers include <ddb/...>)\n")
      else()
        # A relative path into a library folder ("../core/x.h") works only in the tree.
        get_filename_component(target "${folder}/${path}" ABSOLUTE)
        file(RELATIVE_PATH relative "${SOURCE_DIR}" "${target}")
        if(relative MATCHES "^(${parts_pattern})/" OR relative STREQUAL "ddb.h")
          string(APPEND errors "  ${file}: ${line}  (a relative path into the library; write "
                               "<ddb/${relative}>)\n")
        endif()
      endif()
    endif()
  endforeach()
endforeach()

list(LENGTH library_files library_count)
list(LENGTH user_files user_count)
if(library_count LESS 40)
  message(FATAL_ERROR "found only ${library_count} library headers under ${SOURCE_DIR}")
endif()
if(errors)
  message(FATAL_ERROR "includes that would break once installed:\n${errors}")
endif()
message(STATUS "${library_count} library headers and ${user_count} other sources include "
               "the library as <ddb/...> only")
