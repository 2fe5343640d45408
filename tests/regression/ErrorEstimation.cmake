# The experimental dual-weighted-residual estimate (docs/theory.md §7) vanishes where the
# response has no discretization error (the channel's wall force, exact by equilibrium).
set(FLOWFORM_PYTHON /usr/bin/python3)
add_test(NAME error_estimate_vanishes_for_exact_reaction
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/error_estimate_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/error_estimate)
set_tests_properties(error_estimate_vanishes_for_exact_reaction PROPERTIES LABELS "regression")
