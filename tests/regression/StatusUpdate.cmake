# The default contact-status update (Certain Iterate) ends in the paper's loop's state
# (Converged State): the same statuses at every wall node and the same ram force to 1e-6, on
# the plane and axisymmetric extrusion at ν = 0, 0.05, 0.1, 0.2, 0.3, 0.5
# (tests/regression/status_update_checks.py; docs/contact.md).
add_test(NAME status_update_equals_reference
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/status_update_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/status_update)
set_tests_properties(status_update_equals_reference PROPERTIES LABELS "regression" TIMEOUT 900)
