# The two-level error estimate and the adaptive loop (docs/theory.md §7): zero where the
# response is exact (channel wall force), effectivity on the extrusion against Richardson
# references, the adaptive loop meeting a 0.5 % target, bad input.
add_test(NAME error_estimate_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/error_estimate_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/error_estimate)
set_tests_properties(error_estimate_checks PROPERTIES LABELS "regression")
