# Regenerates the reports into OUT and fails when any committed .md or .csv
# in SOURCE/reports differs from what the code now produces, or is missing.
# PNGs are rendered from the same data but depend on gnuplot and fonts.
execute_process(COMMAND ${SWEETSPOT} report --designs ${SOURCE}/designs --out ${OUT}
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "sweetspot report failed with status ${status}")
endif()
file(GLOB_RECURSE committed RELATIVE ${SOURCE}/reports ${SOURCE}/reports/*.md ${SOURCE}/reports/*.csv)
file(GLOB_RECURSE produced RELATIVE ${OUT} ${OUT}/*.md ${OUT}/*.csv)
list(SORT committed)
list(SORT produced)
if(NOT committed STREQUAL produced)
  message(FATAL_ERROR "reports/ holds [${committed}] but the code writes [${produced}]: run scripts/run and commit")
endif()
foreach(name IN LISTS produced)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${SOURCE}/reports/${name} ${OUT}/${name}
                  RESULT_VARIABLE differs)
  if(differs)
    message(FATAL_ERROR "reports/${name} differs from what the code now produces: run scripts/run and commit")
  endif()
endforeach()
message(STATUS "reports/: ${produced} match the code")
