# A backend of the library (CONTRIBUTING.md, "A backend"): a folder of the tree (distributed/,
# cuda/) whose backend.cmake, included once from the top-level CMakeLists.txt, finds what the
# backend needs and, when it is found, calls ddb_add_backend. Everything else that knows about
# backends reads what these functions record, or finds the folders by their backend.cmake: the
# package's config (which components exist, why one was not built, cmake/ddbConfig.cmake.in), the
# tests (tests/CMakeLists.txt includes each built backend's tests file) and the include check
# (tests/checks/check_includes.cmake).

# ddb_declare_backend(<name> TITLE <title> WITHOUT <text>): the package's component <name>
# exists, <title> names it in messages ("CUDA backend"), and <text> says what to do where this ddb
# was installed without it (the backend was not built).
function(ddb_declare_backend name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "TITLE;WITHOUT" "")
  set_property(GLOBAL APPEND PROPERTY DDB_BACKEND_NAMES ${name})
  set_property(GLOBAL PROPERTY DDB_BACKEND_TITLE_${name} "${arg_TITLE}")
  set_property(GLOBAL PROPERTY DDB_BACKEND_WITHOUT_${name} "${arg_WITHOUT}")
endfunction()

# ddb_add_backend(<name> [SOURCES <file>...] LINK <item>... [DEFINITIONS <definition>...]
#                 [TESTS <file>]):
#   - the folder of the calling backend.cmake as <ddb/<folder>/...> in the build tree, and its
#     headers installed as include/ddb/<folder>/;
#   - the target ddb_<name> (ddb::<name>): a static library of SOURCES, or an interface library
#     without them, linking ddb and LINK, with the compile DEFINITIONS for its users;
#   - the package's component <name>: the target in the export set ddb<Name>Targets, and the
#     folder's component.cmake.in configured (@ONLY) and installed as ddb-<name>-component.cmake,
#     which the package's config includes when a consumer asks for the component: it finds the
#     backend's dependencies again and includes the export set, or sets ddb_component_missing;
#   - TESTS, a file of tests/ that tests/CMakeLists.txt includes (in its scope).
# The static library's install is OPTIONAL behind a message: a tree where only the library was
# built (cmake --build --target ddb) installs without the backend and says so, and the package's
# config refuses the component, naming the missing file (ddb_library_<name>).
function(ddb_add_backend name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "TESTS" "SOURCES;LINK;DEFINITIONS")
  set(folder_path ${CMAKE_CURRENT_LIST_DIR})
  get_filename_component(folder ${folder_path} NAME)
  string(SUBSTRING ${name} 0 1 first)
  string(TOUPPER ${first} first)
  string(SUBSTRING ${name} 1 -1 rest)
  set(export_set ddb${first}${rest}Targets)

  file(CREATE_LINK ${folder_path} ${ddb_build_include}/ddb/${folder} SYMBOLIC)
  if(arg_SOURCES)
    add_library(ddb_${name} STATIC ${arg_SOURCES})
    target_link_libraries(ddb_${name} PUBLIC ddb ${arg_LINK})
    target_compile_definitions(ddb_${name} PUBLIC ${arg_DEFINITIONS})
    # Position-independent, as the library: the Python module links both into a shared object.
    set_target_properties(ddb_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    install(CODE "if(NOT EXISTS \"$<TARGET_FILE:ddb_${name}>\")
      message(STATUS \"Skipping $<TARGET_FILE_NAME:ddb_${name}>: it was not built \"
                     \"(cmake --build first to install the component ${name})\")
    endif()")
    install(TARGETS ddb_${name} EXPORT ${export_set} OPTIONAL)
    set_property(GLOBAL PROPERTY DDB_BACKEND_LIBRARY_${name}
                 ${CMAKE_STATIC_LIBRARY_PREFIX}ddb_${name}${CMAKE_STATIC_LIBRARY_SUFFIX})
  else()
    add_library(ddb_${name} INTERFACE)
    target_link_libraries(ddb_${name} INTERFACE ddb ${arg_LINK})
    target_compile_definitions(ddb_${name} INTERFACE ${arg_DEFINITIONS})
    install(TARGETS ddb_${name} EXPORT ${export_set})
  endif()
  add_library(ddb::${name} ALIAS ddb_${name})
  set_target_properties(ddb_${name} PROPERTIES EXPORT_NAME ${name})
  install(DIRECTORY ${folder_path} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ddb
          FILES_MATCHING PATTERN "*.h")
  install(EXPORT ${export_set} NAMESPACE ddb:: DESTINATION ${CMAKE_INSTALL_DATADIR}/ddb/cmake)
  set(component_file ${PROJECT_BINARY_DIR}/ddb-${name}-component.cmake)
  configure_file(${folder_path}/component.cmake.in ${component_file} @ONLY)
  install(FILES ${component_file} DESTINATION ${CMAKE_INSTALL_DATADIR}/ddb/cmake)

  set_property(GLOBAL APPEND PROPERTY DDB_BACKEND_BUILT ${name})
  if(arg_TESTS)
    set_property(GLOBAL APPEND PROPERTY DDB_BACKEND_TESTS ${arg_TESTS})
  endif()
endfunction()

# The lines of the package's config that name every declared component, those built, and what to
# do without each: ddb_components, ddb_built_components, ddb_title_<name>, ddb_without_<name>
# and, for a backend with a static library, its file's name ddb_library_<name>
# (cmake/ddbConfig.cmake.in). The texts go in bracket arguments, taken as they are.
function(ddb_backend_config_lines out)
  get_property(names GLOBAL PROPERTY DDB_BACKEND_NAMES)
  get_property(built GLOBAL PROPERTY DDB_BACKEND_BUILT)
  set(lines "set(ddb_components ${names})\nset(ddb_built_components ${built})\n")
  foreach(name IN LISTS names)
    get_property(title GLOBAL PROPERTY DDB_BACKEND_TITLE_${name})
    get_property(without GLOBAL PROPERTY DDB_BACKEND_WITHOUT_${name})
    get_property(library GLOBAL PROPERTY DDB_BACKEND_LIBRARY_${name})
    string(APPEND lines "set(ddb_title_${name} [==[${title}]==])\n"
                        "set(ddb_without_${name} [==[${without}]==])\n"
                        "set(ddb_library_${name} [==[${library}]==])\n")
  endforeach()
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()
