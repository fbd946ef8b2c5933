# lfd_bake_assets(TARGET name FILES scene.gltf ... [DISPLAY profile.json]
#                 [OUTPUT_DIR dir] [OPTIONS lfd-bake flags ...])
#
# One build rule per asset: FILE -> OUTPUT_DIR/<file stem>.lfdpack, run by `lfd::bake`
# (lfd-bake) with --depfile, so the build system knows every file each bake read (the glTF,
# its buffers and images, the display profile) and rebakes only the packs whose inputs
# changed - or whose baker did. The rules are plain custom commands: Ninja or Make run
# them in parallel, and any build engine that distributes Ninja/Make rules runs them too.
# `name` is a target (built by default) that depends on every pack. docs/baker/batch-baking.md.
function(lfd_bake_assets)
  cmake_parse_arguments(PARSE_ARGV 0 LFD "" "TARGET;DISPLAY;OUTPUT_DIR" "FILES;OPTIONS")
  if(NOT LFD_TARGET)
    message(FATAL_ERROR "lfd_bake_assets: TARGET is required")
  endif()
  if(NOT LFD_FILES)
    message(FATAL_ERROR "lfd_bake_assets(${LFD_TARGET}): FILES is empty")
  endif()
  if(NOT TARGET lfd::bake)
    message(FATAL_ERROR "lfd_bake_assets(${LFD_TARGET}): no lfd::bake executable (find_package(lfd) first)")
  endif()
  if(NOT LFD_OUTPUT_DIR)
    set(LFD_OUTPUT_DIR "${CMAKE_CURRENT_BINARY_DIR}/${LFD_TARGET}")
  endif()
  file(MAKE_DIRECTORY "${LFD_OUTPUT_DIR}")
  set(display_args "")
  set(display_dep "")
  if(LFD_DISPLAY)
    get_filename_component(display "${LFD_DISPLAY}" ABSOLUTE)
    set(display_args --display "${display}")
    set(display_dep "${display}")
  endif()

  set(packs "")
  set(stems "")
  foreach(asset IN LISTS LFD_FILES)
    get_filename_component(source "${asset}" ABSOLUTE)
    get_filename_component(stem "${asset}" NAME_WLE)
    if(stem IN_LIST stems)
      message(FATAL_ERROR "lfd_bake_assets(${LFD_TARGET}): two assets named '${stem}' would write the same pack "
                          "(${source}); bake them into different OUTPUT_DIRs")
    endif()
    list(APPEND stems "${stem}")
    set(pack "${LFD_OUTPUT_DIR}/${stem}.lfdpack")
    add_custom_command(
      OUTPUT "${pack}"
      COMMAND lfd::bake "${source}" -o "${pack}" --depfile "${pack}.d" --quiet ${display_args} ${LFD_OPTIONS}
      DEPENDS "${source}" ${display_dep} "$<TARGET_FILE:lfd::bake>"
      DEPFILE "${pack}.d"
      COMMENT "lfd-bake ${stem}.lfdpack"
      VERBATIM)
    list(APPEND packs "${pack}")
  endforeach()
  add_custom_target(${LFD_TARGET} ALL DEPENDS ${packs})
endfunction()
