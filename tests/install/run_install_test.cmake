# cmake -P run_install_test.cmake: the CTest test install/consumer (tests/install/CMakeLists.txt).
#
# 1. cmake --install BUILD_DIR --prefix WORK_DIR/prefix --component development;
# 2. the installed CMake files must name no folder of the source or build tree (the
#    package is relocatable: everything relative to the prefix or found again);
# 3. CONSUMER_DIR configured against that prefix only (CMAKE_PREFIX_PATH, no package
#    registry), and gjkx must be found there; built with the build's compiler;
# 4. both programs run: each returns nonzero unless its result is right and must end with
#    OK; the time of impact must read 0.4999999... and a hit.
foreach(var BUILD_DIR SOURCE_DIR CONSUMER_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_install_test.cmake: -D${var}= is missing")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install test: ${what} failed (${rc}):\n${ARGN}\n${out}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

set(config_args "")
if(CONFIG)
  set(config_args --config ${CONFIG})
endif()
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --component development ${config_args})

file(GLOB_RECURSE installed_cmake ${prefix}/*.cmake)
if(NOT installed_cmake)
  message(FATAL_ERROR "install test: no CMake file installed under ${prefix}")
endif()
foreach(file IN LISTS installed_cmake)
  file(READ ${file} text)
  foreach(tree ${SOURCE_DIR} ${BUILD_DIR})
    string(FIND "${text}" "${tree}/" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "install test: ${file} names ${tree}, which a user does not have")
    endif()
  endforeach()
endforeach()

set(consumer_args -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON
                  -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
if(CONFIG)
  list(APPEND consumer_args -DCMAKE_BUILD_TYPE=${CONFIG})
endif()
if(CXX_COMPILER_LAUNCHER)
  list(APPEND consumer_args -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_COMPILER_LAUNCHER})
endif()
run("configuring the consumer" ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${build} ${consumer_args})
file(STRINGS ${build}/CMakeCache.txt found REGEX "^gjkx_DIR:")
if(NOT found STREQUAL "gjkx_DIR:PATH=${prefix}/lib/cmake/gjkx")
  message(FATAL_ERROR "install test: the consumer found gjkx elsewhere than in ${prefix}: ${found}")
endif()
run("building the consumer" ${CMAKE_COMMAND} --build ${build} ${config_args} --parallel 2)

foreach(program toi_boxes every_stage)
  find_program(path_${program} ${program} PATHS ${build} ${build}/${CONFIG} NO_DEFAULT_PATH REQUIRED)
  run("${program}" ${path_${program}})
  message(STATUS "${program}:\n${output}")
  if(NOT output MATCHES "\nOK\n$")
    message(FATAL_ERROR "install test: ${program} did not end with OK")
  endif()
  # Besides the program's own check: the two cubes' faces meet at t = 1/2 (less a quarter
  # of the tolerance, 3.7e-9 in double).
  if(program STREQUAL "toi_boxes" AND NOT output MATCHES "^time of impact 0\\.4999999[0-9]* .* status hit ")
    message(FATAL_ERROR "install test: toi_boxes did not print a hit at 0.4999999...")
  endif()
endforeach()
