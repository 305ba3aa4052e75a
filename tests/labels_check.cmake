# cmake -DCTEST=... -DBUILD_DIR=... -P labels_check.cmake
# Fails when a test of this build carries none of the suite's labels: ctest -L would then never select it.
execute_process(COMMAND ${CTEST} --test-dir ${BUILD_DIR} -N -LE "^(unit|cli|gui|fuzz|format|install)$"
                OUTPUT_VARIABLE listing RESULT_VARIABLE result)
if(NOT result EQUAL 0 OR NOT listing MATCHES "Total Tests: 0")
  message(FATAL_ERROR "tests without a label (add LABELS in tests/CMakeLists.txt):\n${listing}")
endif()
execute_process(COMMAND ${CTEST} --test-dir ${BUILD_DIR} -N -L "^unit$" OUTPUT_VARIABLE listing)
if(NOT listing MATCHES "Total Tests: [1-9]")
  message(FATAL_ERROR "no test labelled unit:\n${listing}")
endif()
