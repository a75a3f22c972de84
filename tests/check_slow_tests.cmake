# Every name tests/slow_tests.cmake labels `slow` is a test of this build:
# ctest lists as many tests under the label as the file names.
#   cmake -DCTEST=... -DBUILD=... -DLIST=tests/slow_tests.cmake -P check_slow_tests.cmake
file(STRINGS "${LIST}" lines REGEX "^    \"[a-z]+:")
list(LENGTH lines named)
execute_process(COMMAND "${CTEST}" --test-dir "${BUILD}" -N -L slow
                OUTPUT_VARIABLE listed RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ctest -N -L slow failed: ${status}")
endif()
string(REGEX MATCH "Total Tests: ([0-9]+)" _ "${listed}")
if(NOT CMAKE_MATCH_1 EQUAL named)
  message(FATAL_ERROR "${LIST} names ${named} tests, ctest labels ${CMAKE_MATCH_1} slow: "
                      "a name there is no test's any longer\n${listed}")
endif()
message(STATUS "${named} slow tests, each a test of this build")
