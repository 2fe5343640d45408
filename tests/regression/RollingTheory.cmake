# The rolling slab theory (python/flowform_tools/rolling_theory.py, docs/rolling_theory.md)
# against closed forms it does not compute itself (Bland & Ford, Sims, the frictionless drawing
# solution, Tresca's closed neutral point), exact identities (power, mass) and Hill's fit within
# its range (regression/rolling_theory_checks.py). No flowform run: numpy only, a few seconds.
add_test(NAME rolling_theory
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/rolling_theory_checks.py)
set_tests_properties(rolling_theory PROPERTIES LABELS "regression" TIMEOUT 60)
