# Every dependency is a Debian package installed by scripts/setup.sh.
find_package(glm REQUIRED CONFIG)
find_package(OpenImageIO REQUIRED CONFIG)
# Debian's OpenImageIO config names /usr/include/opencv4 although libopencv-dev is not needed
# (nor installed): drop the dangling include path so that linking the target works.
foreach(property INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  get_target_property(dirs OpenImageIO::OpenImageIO ${property})
  if(dirs)
    list(FILTER dirs EXCLUDE REGEX "opencv")
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${property} "${dirs}")
  endif()
endforeach()
find_package(assimp REQUIRED CONFIG)
find_package(zstd REQUIRED CONFIG)
find_package(CLI11 REQUIRED CONFIG)
find_package(nlohmann_json REQUIRED CONFIG)
find_package(meshoptimizer REQUIRED CONFIG)
find_package(GTest REQUIRED CONFIG)
find_package(benchmark REQUIRED CONFIG)
find_package(Threads REQUIRED)
# Block-compressed textures (texcodec/): ARM's ASTC codec and libsquish (BC1-BC5 encoder).
find_package(astcenc REQUIRED CONFIG)
find_library(SQUISH_LIBRARY squish REQUIRED)
find_path(SQUISH_INCLUDE_DIR squish.h REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)

# LEMON ships a config file that sets variables only; wrap it in a target.
find_package(lemon REQUIRED CONFIG)
if(NOT TARGET lemon::lemon)
  add_library(lemon::lemon UNKNOWN IMPORTED)
  set_target_properties(lemon::lemon PROPERTIES
    IMPORTED_LOCATION "${LEMON_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${LEMON_INCLUDE_DIR}")
endif()
