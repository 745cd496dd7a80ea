# CMake helpers of the gjkx house. Adding a stage, a chapter or a test is one
# line: gjkx_stage(), gjkx_chapter(), gjkx_test().

include(GNUInstallDirs)   # CMAKE_INSTALL_INCLUDEDIR, CMAKE_INSTALL_LIBDIR

# Warnings for every target of the project (Eigen comes in as a system include).
function(gjkx_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(GJKX_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# gjkx_stage(<name> [DEPENDS <earlier stages>...] [LINKS <external targets>...] [NOT_EXPORTED])
#
# lib/<name>/include holds the headers <gjkx/<name>/*.hpp>, lib/<name>/src the
# sources (if any; a stage without sources is header only). The target is
# gjkx::<name>. A stage may depend only on stages already declared, so the order
# of the gjkx_stage() lines in lib/CMakeLists.txt is the order of the paper.
#
# `cmake --install` installs every stage's headers and library, and the package
# (cmake/gjkx_package.cmake) exports every stage as gjkx::<name> for a user's
# find_package(gjkx), unless NOT_EXPORTED (what only the project's own programs link).
# Every external target in LINKS needs its find_dependency() in the package: an exported
# stage records them here, and gjkx_package.cmake refuses one it does not know.
function(gjkx_stage name)
  cmake_parse_arguments(ARG "NOT_EXPORTED" "" "DEPENDS;LINKS" ${ARGN})
  get_property(unexported GLOBAL PROPERTY GJKX_UNEXPORTED_STAGES)
  foreach(dep IN LISTS ARG_DEPENDS)
    if(NOT TARGET gjkx::${dep})
      message(FATAL_ERROR "stage ${name} depends on ${dep}, which is not an earlier stage")
    endif()
    if(NOT ARG_NOT_EXPORTED AND dep IN_LIST unexported)
      message(FATAL_ERROR "stage ${name} is exported but depends on ${dep}, which is NOT_EXPORTED")
    endif()
  endforeach()
  set(dir ${CMAKE_CURRENT_SOURCE_DIR}/${name})
  file(GLOB sources CONFIGURE_DEPENDS ${dir}/src/*.cpp)
  list(TRANSFORM ARG_DEPENDS PREPEND gjkx:: OUTPUT_VARIABLE deps)
  set(includes $<BUILD_INTERFACE:${dir}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  if(sources)
    add_library(gjkx_${name} STATIC ${sources})
    target_include_directories(gjkx_${name} PUBLIC ${includes})
    target_link_libraries(gjkx_${name} PUBLIC ${deps} Eigen3::Eigen PRIVATE ${ARG_LINKS})
    gjkx_warnings(gjkx_${name})
  else()
    add_library(gjkx_${name} INTERFACE)
    target_include_directories(gjkx_${name} INTERFACE ${includes})
    target_link_libraries(gjkx_${name} INTERFACE ${deps} Eigen3::Eigen ${ARG_LINKS})
  endif()
  add_library(gjkx::${name} ALIAS gjkx_${name})
  set_target_properties(gjkx_${name} PROPERTIES EXPORT_NAME ${name})
  set_property(GLOBAL APPEND PROPERTY GJKX_STAGES ${name})
  # `cmake --install build --prefix DIR`: the stage's headers and, if it has sources, its
  # library; in the component `development`, which is all a user's project needs.
  install(DIRECTORY ${dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT development)
  if(ARG_NOT_EXPORTED)
    set_property(GLOBAL APPEND PROPERTY GJKX_UNEXPORTED_STAGES ${name})
    if(sources)
      install(TARGETS gjkx_${name} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
    endif()
  else()
    set_property(GLOBAL APPEND PROPERTY GJKX_EXPORTED_STAGES ${name})
    set_property(GLOBAL APPEND PROPERTY GJKX_EXPORTED_LINKS Eigen3::Eigen ${ARG_LINKS})
    install(TARGETS gjkx_${name} EXPORT gjkxTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
  endif()
endfunction()

# gjkx_chapter(<NN_name> [THREE_D] STAGES <stages>...)
#
# chapters/<NN_name>/main.cpp, linked with its stages, the renderer and CLI11 (the
# command line). Every chapter takes --out DIR and --format png|svg|pdf and writes its
# figures there; the target `figures` runs them all for figures/. THREE_D: the chapter
# draws 3D figures, so it needs OSMesa.
function(gjkx_chapter name)
  cmake_parse_arguments(ARG "THREE_D" "" "STAGES" ${ARGN})
  if(NOT GJKX_HAVE_RENDER OR (ARG_THREE_D AND NOT GJKX_HAVE_OSMESA))
    set_property(GLOBAL APPEND PROPERTY GJKX_SKIPPED_CHAPTERS ${name})
    return()
  endif()
  list(TRANSFORM ARG_STAGES PREPEND gjkx:: OUTPUT_VARIABLE stages)
  add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/${name}/main.cpp)
  target_link_libraries(${name} PRIVATE ${stages} gjkx::render CLI11::CLI11)
  gjkx_warnings(${name})
  set_property(GLOBAL APPEND PROPERTY GJKX_CHAPTERS ${name})
endfunction()

# gjkx_program(<name> SOURCE <chapters/... file> STAGES <stages>...)
#
# A command-line program of a chapter that draws nothing (it prints tables), so it
# builds without the renderer too; e.g. ccd_queries in chapter 05. Its command line
# goes through CLI11, as every program's does.
function(gjkx_program name)
  cmake_parse_arguments(ARG "" "SOURCE" "STAGES" ${ARGN})
  list(TRANSFORM ARG_STAGES PREPEND gjkx:: OUTPUT_VARIABLE stages)
  add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/${ARG_SOURCE})
  target_link_libraries(${name} PRIVATE ${stages} CLI11::CLI11)
  gjkx_warnings(${name})
endfunction()

# gjkx_test(<stage> <concept> [LINKS <extra targets>...])
#
# tests/<stage>/test_<concept>.cpp, a Catch2 test linked with gjkx::<stage>.
# Each TEST_CASE becomes one CTest test.
function(gjkx_test stage concept)
  cmake_parse_arguments(ARG "" "" "LINKS" ${ARGN})
  set(name test_${stage}_${concept})
  add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/${stage}/test_${concept}.cpp)
  target_link_libraries(${name} PRIVATE gjkx::${stage} gjkx_catch_main ${ARG_LINKS})
  gjkx_warnings(${name})
  target_precompile_headers(${name} REUSE_FROM gjkx_test_pch)
  catch_discover_tests(${name} EXTRA_ARGS --warn NoTests TEST_PREFIX "${stage}/" PROPERTIES LABELS ${stage})
endfunction()

# Says, at the end of configuration, which chapters a build without the renderer (or OSMesa) left out.
function(gjkx_report_skipped)
  get_property(skipped GLOBAL PROPERTY GJKX_SKIPPED_CHAPTERS)
  if(skipped)
    list(JOIN skipped ", " text)
    message(WARNING "gjkx: no renderer (Cairo and Pango), or no OSMesa for the 3D figures: chapters skipped: ${text}")
  endif()
endfunction()
