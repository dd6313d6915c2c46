set(RASTRACE_WARNINGS -Wall -Wextra -Wpedantic)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  # GCC 12 reports a false -Wrestrict inside libstdc++ for `"literal" + std::string` at -O2
  # (GCC bug 105651, fixed in 13); it is noise, not a finding about our code.
  list(APPEND RASTRACE_WARNINGS -Wno-restrict)
endif()
if(RASTRACE_WERROR)
  list(APPEND RASTRACE_WARNINGS -Werror)
endif()

# rastrace_module(NAME SOURCES... DEPENDS targets...) declares one module library whose public
# headers are included as "NAME/header.h" from the repository root (from include/rastrace once
# installed: cmake/Install.cmake).
function(rastrace_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                            $<INSTALL_INTERFACE:include/rastrace> $<INSTALL_INTERFACE:include>)
  target_link_libraries(${name} PUBLIC ${ARG_DEPENDS})
endfunction()
