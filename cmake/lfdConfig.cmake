# find_package(lfd): the installed toolkit's executables as imported targets (lfd::bake,
# lfd::play, lfd::bench, lfd::compare, lfd::make_samples, where installed) and
# lfd_bake_assets() for batch baking (LfdBakeAssets.cmake). Installed to
# <prefix>/lib/cmake/lfd by `cmake --install`.
get_filename_component(LFD_PREFIX "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
set(LFD_PROFILES_DIR "${LFD_PREFIX}/share/lfd/profiles")
foreach(tool bake play bench compare make-samples)
  string(REPLACE "-" "_" name "${tool}")
  if(NOT TARGET lfd::${name} AND EXISTS "${LFD_PREFIX}/bin/lfd-${tool}")
    add_executable(lfd::${name} IMPORTED)
    set_target_properties(lfd::${name} PROPERTIES IMPORTED_LOCATION "${LFD_PREFIX}/bin/lfd-${tool}")
  endif()
endforeach()
if(NOT TARGET lfd::bake)
  set(lfd_FOUND FALSE)
  set(lfd_NOT_FOUND_MESSAGE "lfd-bake is not installed under ${LFD_PREFIX}/bin")
  return()
endif()
include("${CMAKE_CURRENT_LIST_DIR}/LfdBakeAssets.cmake")
