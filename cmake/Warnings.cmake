set(RASTRACE_WARNINGS -Wall -Wextra -Wpedantic)
if(RASTRACE_WERROR)
  list(APPEND RASTRACE_WARNINGS -Werror)
endif()

# rastrace_module(NAME SOURCES... DEPENDS targets...) declares one module library whose public
# headers are included as "NAME/header.h" from the repository root.
function(rastrace_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPENDS})
endfunction()
