# The docs test (docs/no_doxygen_warnings): run Doxygen and fail if it warned.
#
#   cmake -D DOXYGEN=<doxygen> -D DOXYFILE=<Doxyfile> -D OUTPUT_DIR=<dir>
#         -D LOGFILE=<warnings log> -P check_doxygen.cmake
#
# Every warning is a fault of the docs a reader would meet: a public name without
# documentation, a \ref to nothing, a figure missing from figures/, a formula that
# does not parse. The log is printed so the test output says what to fix.
foreach(var DOXYGEN DOXYFILE OUTPUT_DIR LOGFILE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_doxygen.cmake: -D ${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE ${OUTPUT_DIR})
file(MAKE_DIRECTORY ${OUTPUT_DIR})

execute_process(
  COMMAND ${DOXYGEN} ${DOXYFILE}
  WORKING_DIRECTORY ${OUTPUT_DIR}
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "doxygen failed (exit ${result}):\n${output}${errors}")
endif()
if(NOT EXISTS ${LOGFILE})
  message(FATAL_ERROR "doxygen wrote no warnings log at ${LOGFILE}:\n${output}${errors}")
endif()

file(READ ${LOGFILE} warnings)
string(STRIP "${warnings}" warnings)
if(NOT warnings STREQUAL "")
  string(REGEX MATCHALL "\n" lines "\n${warnings}")
  list(LENGTH lines count)
  message("${warnings}\n")
  message(FATAL_ERROR "Doxygen warned (${count} lines above, log: ${LOGFILE})")
endif()
message(STATUS "Doxygen: no warnings (${OUTPUT_DIR}/html/index.html)")
