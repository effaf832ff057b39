# Fails if a library header includes one of a higher layer (docs/design/architecture.md,
# "Layout"): a folder shows one layer and never includes a higher one. The layers, each
# allowed the ones listed before it on its line:
#   core → groups → systems
#   core → groups → integrators/matrix_kernels → integrators/solvers → integrators/methods
#        → integrators/drivers
# (systems and integrators are independent: a method never names a system, a system never a
# method). instantiations/ and ddb.h are the top and may include anything; the deprecated
# forwarding headers at integrators/*.h include the header they forward to.
#   cmake -DSOURCE_DIR=<tree> -P tests/checks/check_layers.cmake
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...)
if(NOT IS_DIRECTORY "${SOURCE_DIR}")
  message(FATAL_ERROR "set SOURCE_DIR to the ddb source tree")
endif()

# Each layer and what it may include (itself included).
set(allowed_core core)
set(allowed_groups core groups)
set(allowed_systems core groups systems)
set(allowed_integrators/matrix_kernels core groups integrators/matrix_kernels)
set(allowed_integrators/solvers ${allowed_integrators/matrix_kernels} integrators/solvers)
set(allowed_integrators/methods ${allowed_integrators/solvers} integrators/methods)
set(allowed_integrators/drivers ${allowed_integrators/methods} integrators/drivers)
set(layers core groups systems integrators/matrix_kernels integrators/solvers
           integrators/methods integrators/drivers)
# The one include of a higher layer allowed, "file:included": integrate()'s location before
# 0.3.0, kept until 0.4.0 (CHANGELOG, "Deprecated").
set(allowed_upward "integrators/methods/one_step_method.h:integrators/drivers/integrate.h")

# The layer of a path inside the library ("core/detail/x.h" is core's).
function(layer_of path result)
  set(found "")
  foreach(layer IN LISTS layers)
    string(LENGTH "${layer}/" length)
    string(SUBSTRING "${path}" 0 ${length} head)
    if(head STREQUAL "${layer}/")
      set(found "${layer}")
    endif()
  endforeach()
  set(${result} "${found}" PARENT_SCOPE)
endfunction()

set(errors "")
set(checked 0)
foreach(layer IN LISTS layers)
  file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${layer}/*.h"
       "${SOURCE_DIR}/${layer}/*.cc")
  foreach(file IN LISTS files)
    layer_of("${file}" own)
    if(NOT own STREQUAL layer)
      continue()  # a deeper layer's file, checked with its own layer
    endif()
    math(EXPR checked "${checked} + 1")
    file(STRINGS "${SOURCE_DIR}/${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*<ddb/")
    foreach(line IN LISTS lines)
      string(REGEX MATCH "<ddb/([^>]+)>" _ "${line}")
      layer_of("${CMAKE_MATCH_1}" target)
      if("${file}:${CMAKE_MATCH_1}" IN_LIST allowed_upward)
        continue()
      endif()
      if(target STREQUAL "")
        string(APPEND errors "  ${file}: ${line}  (a ${layer} file includes above every layer)\n")
      elseif(NOT target IN_LIST allowed_${layer})
        string(APPEND errors "  ${file}: ${line}  (${layer} may include only: "
                             "${allowed_${layer}})\n")
      endif()
    endforeach()
  endforeach()
endforeach()

if(checked LESS 60)
  message(FATAL_ERROR "found only ${checked} library files under ${SOURCE_DIR}")
endif()
if(errors)
  message(FATAL_ERROR "includes of a higher layer:\n${errors}")
endif()
message(STATUS "${checked} library files include only their own layer and the ones below it")
