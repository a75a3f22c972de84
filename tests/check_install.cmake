# Installs sweetspot into a scratch prefix and builds examples/consumer against
# it with find_package(sweetspot); the consumer must print Table I's top row.
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/prefix
                RESULT_VARIABLE status OUTPUT_QUIET)
if(status)
  message(FATAL_ERROR "install failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/examples/consumer -B ${WORK}/build
                        -DCMAKE_PREFIX_PATH=${WORK}/prefix RESULT_VARIABLE status OUTPUT_QUIET)
if(status)
  message(FATAL_ERROR "find_package(sweetspot) failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/build RESULT_VARIABLE status OUTPUT_QUIET)
if(status)
  message(FATAL_ERROR "the consumer did not build")
endif()
execute_process(COMMAND ${WORK}/build/consumer OUTPUT_VARIABLE printed RESULT_VARIABLE status)
if(status OR NOT printed MATCHES "F0 = 1117 N, F_w = 568 N")
  message(FATAL_ERROR "the consumer printed '${printed}'")
endif()
message(STATUS "installed sweetspot consumed: ${printed}")

# The same consumer against the build tree, without installing: the exported
# targets file beside sweetspotConfig.cmake in the build directory.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/examples/consumer -B ${WORK}/build-tree
                        -Dsweetspot_DIR=${BUILD} RESULT_VARIABLE status OUTPUT_QUIET)
if(status)
  message(FATAL_ERROR "find_package(sweetspot) from the build tree failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/build-tree RESULT_VARIABLE status OUTPUT_QUIET)
if(status)
  message(FATAL_ERROR "the consumer did not build against the build tree")
endif()
execute_process(COMMAND ${WORK}/build-tree/consumer OUTPUT_VARIABLE printed RESULT_VARIABLE status)
if(status OR NOT printed MATCHES "F0 = 1117 N, F_w = 568 N")
  message(FATAL_ERROR "the build-tree consumer printed '${printed}'")
endif()
message(STATUS "build-tree sweetspot consumed: ${printed}")

# The README's library snippet (the ```cpp block after its marker line),
# built against the installed package with the consumer's CMakeLists.txt:
# it must compile as written and print Table I's top row.
file(READ ${SOURCE}/README.md readme)
string(FIND "${readme}" "<!-- compiled and run by tests/check_install.cmake -->" marker)
if(marker EQUAL -1)
  message(FATAL_ERROR "README.md has no library snippet marked for this test")
endif()
string(SUBSTRING "${readme}" ${marker} -1 readme)
string(FIND "${readme}" "```cpp\n" start)
string(FIND "${readme}" "\n```\n" end)
if(start EQUAL -1 OR end EQUAL -1 OR end LESS start)
  message(FATAL_ERROR "README.md: no ```cpp block after the library snippet's marker")
endif()
math(EXPR start "${start} + 7")
math(EXPR length "${end} + 1 - ${start}")
string(SUBSTRING "${readme}" ${start} ${length} snippet)
file(WRITE ${WORK}/readme-snippet/main.cpp "${snippet}")
configure_file(${SOURCE}/examples/consumer/CMakeLists.txt ${WORK}/readme-snippet/CMakeLists.txt COPYONLY)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK}/readme-snippet -B ${WORK}/readme-snippet/build
                        -DCMAKE_PREFIX_PATH=${WORK}/prefix RESULT_VARIABLE status OUTPUT_QUIET)
if(status)
  message(FATAL_ERROR "find_package(sweetspot) failed for the README's snippet")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/readme-snippet/build RESULT_VARIABLE status
                OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(status)
  message(FATAL_ERROR "the README's library snippet did not build:\n${log}")
endif()
execute_process(COMMAND ${WORK}/readme-snippet/build/consumer OUTPUT_VARIABLE printed RESULT_VARIABLE status)
if(status OR NOT printed MATCHES "^F0 = 1117 N, F_w = 568 N, hand-held COP [0-9]+\\.[0-9] cm from the butt\n$")
  message(FATAL_ERROR "the README's library snippet printed '${printed}'")
endif()
message(STATUS "the README's library snippet: ${printed}")
