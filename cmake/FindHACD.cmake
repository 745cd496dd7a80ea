# FindHACD: Khaled Mamou's HACD convex decomposition, as Debian ships it in Bullet's
# extras (libbullet-extras-dev: /usr/include/bullet/HACD/hacdHACD.h, libHACD.so), which
# has no CMake config file of its own.
#
# Defines the imported target HACD::HACD (its include folder is the one that holds
# HACD/hacdHACD.h, so sources write #include <HACD/hacdHACD.h>) and HACD_FOUND. The cache
# variables HACD_INCLUDE_DIR and HACD_LIBRARY point it at another copy.
#
# The project finds HACD through this module (lib/CMakeLists.txt), and so does the
# installed package: gjkxConfig.cmake ships it and finds HACD again the same way, since the
# exported gjkx::mesh links HACD::HACD.
find_path(HACD_INCLUDE_DIR HACD/hacdHACD.h PATH_SUFFIXES bullet)
find_library(HACD_LIBRARY NAMES HACD)
mark_as_advanced(HACD_INCLUDE_DIR HACD_LIBRARY)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(HACD REQUIRED_VARS HACD_LIBRARY HACD_INCLUDE_DIR)

if(HACD_FOUND AND NOT TARGET HACD::HACD)
  add_library(HACD::HACD UNKNOWN IMPORTED)
  set_target_properties(HACD::HACD PROPERTIES
    IMPORTED_LOCATION "${HACD_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${HACD_INCLUDE_DIR}")
endif()
