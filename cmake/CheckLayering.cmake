# The module DAG: the one place that states which library target may link which.
#
# Each entry is "target: the targets directly below it". A target may link any target reachable
# downwards from it in this table (cache_sim may link core, since core is below traces), and no
# other target of the table; libraries from outside the project (glm, zstd, LEMON, ...) are not
# checked. docs/DESIGN.md draws the same graph and points here.
#
# A target that this build does not define (a module that does not exist yet, or an optional one)
# is skipped, but its edges still count: experiments may link reorder through reorder_adjacency
# whether or not reorder_adjacency exists.
set(RASTRACE_MODULE_DAG
  "core:"
  "texcodec: core"
  "scenes: texcodec core"
  "traces: core"
  "cache_sim: traces core"
  "reorder: scenes cache_sim traces core"
  "reorder_adjacency: reorder"
  "lod: reorder cache_sim scenes"
  "overdraw: core"
  "raster: scenes traces"
  "pipeline: raster cache_sim reorder"
  "reference: pipeline"
  "experiments: reference pipeline raster reorder_adjacency reorder lod overdraw cache_sim traces scenes core"
  "rastrace_commands: experiments"
  "rastrace: rastrace_commands"
)

# Fails the configuration, naming the target and the link, if any defined target of the table
# links a table target that is not below it. Call it once every target has been declared.
function(rastrace_check_layering)
  set(known "")
  foreach(entry IN LISTS RASTRACE_MODULE_DAG)
    string(REGEX REPLACE ":.*$" "" name "${entry}")
    string(REGEX REPLACE "^[^:]*:" "" below "${entry}")
    string(STRIP "${below}" below)
    string(REGEX REPLACE "[ \t]+" ";" below "${below}")
    list(APPEND known ${name})
    set(direct_${name} ${below})
  endforeach()

  foreach(target IN LISTS known)
    if(NOT TARGET ${target})
      continue()
    endif()
    # Everything below target: a walk down the table (it is small; no cycle can loop forever
    # because each name is visited once).
    set(allowed "")
    set(pending ${direct_${target}})
    while(pending)
      list(POP_FRONT pending next)
      if(next IN_LIST allowed)
        continue()
      endif()
      list(APPEND allowed ${next})
      list(APPEND pending ${direct_${next}})
    endwhile()

    get_target_property(links ${target} LINK_LIBRARIES)
    get_target_property(interface_links ${target} INTERFACE_LINK_LIBRARIES)
    foreach(link IN LISTS links interface_links)
      # $<LINK_ONLY:x> and similar wrappers: check the target inside.
      string(REGEX REPLACE "^\\$<[A-Z_]+:(.*)>$" "\\1" link "${link}")
      if(link STREQUAL target OR NOT link IN_LIST known)
        continue()
      endif()
      if(NOT link IN_LIST allowed)
        list(JOIN allowed ", " allowed_text)
        if(NOT allowed_text)
          set(allowed_text "nothing of the project")
        endif()
        message(FATAL_ERROR
          "Layering: target '${target}' links '${link}', which is not below it in the module DAG. "
          "'${target}' may link: ${allowed_text}. The DAG is declared in cmake/CheckLayering.cmake "
          "(RASTRACE_MODULE_DAG); a dependency upward means the code belongs in a lower module, "
          "or the table and docs/DESIGN.md must change together.")
      endif()
    endforeach()
  endforeach()
endfunction()
