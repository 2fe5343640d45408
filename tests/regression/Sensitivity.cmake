# Sensitivity analysis (docs/theory.md §4): DDM against the built-in finite-difference check on the
# channel (du/dσ0, du/dn) and the extrusion (dF/dν at several ν), the one-sided flag at a
# stick/slip switch, and what a run without sensitivities costs. `external`: dF/dν against a
# central difference of two independent full runs, with the walls' Penalty Viscosity fixed
# (the adaptive penalty scales depend on the solution, which the DDM holds fixed). Each test is one subcommand
# of regression/sensitivity_checks.py (tolerances justified there and in docs/sensitivity.md).
foreach(sub channel extrusion external one-sided no-work shape)
  add_test(NAME sensitivity_${sub}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/sensitivity_checks.py ${sub}
                   $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/sensitivity/${sub})
  set_tests_properties(sensitivity_${sub} PROPERTIES LABELS "regression" TIMEOUT 300)
endforeach()
# The checker can fail: with δ = 5 % of σ0 and n the truncation error is far above 1e-5.
add_test(NAME sensitivity_channel_coarse_step_fails
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/sensitivity_checks.py channel
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/sensitivity/coarse --step 0.05)
set_tests_properties(sensitivity_channel_coarse_step_fails PROPERTIES LABELS "regression" WILL_FAIL TRUE TIMEOUT 300)
# A finite-difference run that does not converge (n − δ = 0 with δ = 100 % of n): exit status
# 3, the flow solution still reported converged, the check's entries "not_converged".
add_test(NAME sensitivity_fd_not_converged_exits_3
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_summary.py --expect-exit 3
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR}/xml/channel.xml
                 ${CMAKE_CURRENT_BINARY_DIR}/sensitivity/fd_not_converged
                 --set "Mesh/Geo Parameters/N=4" --set "Sensitivity/Parameters={Rate Exponent}"
                 --set "Sensitivity/Finite Difference Check=true" --set "Sensitivity/Finite Difference Step=1.0"
                 -- converged=true exit_status=3 sensitivity.finite_difference.all_converged=false
                    "fd_check.velocity_field.Rate Exponent.status=\"not_converged\"")
set_tests_properties(sensitivity_fd_not_converged_exits_3 PROPERTIES LABELS "regression" TIMEOUT 300)
