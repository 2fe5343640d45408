# Moving tools (docs/theory.md §2 "Moving tools", docs/verification.md "Moving tools"): each test is
# one subcommand of regression/moving_tool_checks.py (the derivations and tolerances are in its
# docstring and in docs/verification.md). The bad input and the power balance with a moving
# container are in BadInput.cmake and PowerBalance.cmake.
foreach(sub couette container)
  add_test(NAME moving_tool_${sub}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/moving_tool_checks.py ${sub}
                   $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/moving_tool/${sub})
  set_tests_properties(moving_tool_${sub} PROPERTIES LABELS "regression" TIMEOUT 120)
endforeach()
