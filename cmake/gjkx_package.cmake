# The installed package: `cmake --install build --prefix DIR` writes
# DIR/lib/cmake/gjkx/gjkxConfig.cmake, its version file and the exported targets
# gjkx::<stage> (every stage gjkx_stage() declared without NOT_EXPORTED), so that a
# user's project does
#
#   find_package(gjkx CONFIG REQUIRED)          # CMAKE_PREFIX_PATH=DIR, or gjkx_DIR
#   target_link_libraries(app PRIVATE gjkx::brent)
#
# Included by the top CMakeLists.txt after lib/, when every stage is declared.
# tests/install checks the whole round trip on a consumer project.
include(CMakePackageConfigHelpers)

set(GJKX_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/gjkx)

# The find_dependency() of each external target an exported stage links. Static stages
# link theirs privately, but the export still names them ($<LINK_ONLY:...>) for the
# consumer's link line, so every one must be found again, private or not.
set(gjkx_dependency_Eigen3::Eigen                 "find_dependency(Eigen3 3.3 NO_MODULE)")
set(gjkx_dependency_Qhull::qhull_r                "find_dependency(Qhull)")
set(gjkx_dependency_assimp::assimp                "find_dependency(assimp)")
set(gjkx_dependency_HACD::HACD                    "find_dependency(HACD)   # FindHACD.cmake, installed beside this file")
set(gjkx_dependency_Boost::headers                "find_dependency(Boost 1.71)")
set(gjkx_dependency_nlohmann_json::nlohmann_json  "find_dependency(nlohmann_json 3)")

get_property(gjkx_exported_links GLOBAL PROPERTY GJKX_EXPORTED_LINKS)
list(REMOVE_DUPLICATES gjkx_exported_links)
set(GJKX_FIND_DEPENDENCIES "")
foreach(target IN LISTS gjkx_exported_links)
  if(NOT DEFINED "gjkx_dependency_${target}")
    message(FATAL_ERROR "gjkx: an exported stage links ${target}, but the installed package would not find it "
                        "again: add its find_dependency() to the table in cmake/gjkx_package.cmake "
                        "(or declare the stage NOT_EXPORTED)")
  endif()
  string(APPEND GJKX_FIND_DEPENDENCIES "${gjkx_dependency_${target}}\n")
endforeach()
get_property(GJKX_EXPORTED_STAGES GLOBAL PROPERTY GJKX_EXPORTED_STAGES)
list(JOIN GJKX_EXPORTED_STAGES ", " GJKX_EXPORTED_STAGES_TEXT)
get_property(gjkx_unexported GLOBAL PROPERTY GJKX_UNEXPORTED_STAGES)
if(gjkx_unexported)
  list(JOIN gjkx_unexported ", " gjkx_unexported_text)
  message(STATUS "gjkx package: stages installed but not exported: ${gjkx_unexported_text}")
endif()

install(EXPORT gjkxTargets NAMESPACE gjkx:: DESTINATION ${GJKX_INSTALL_CMAKEDIR} COMPONENT development)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/gjkxConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/gjkxConfig.cmake
  INSTALL_DESTINATION ${GJKX_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change any interface.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/gjkxConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/gjkxConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/gjkxConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/FindHACD.cmake
        DESTINATION ${GJKX_INSTALL_CMAKEDIR} COMPONENT development)
