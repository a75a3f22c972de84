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
