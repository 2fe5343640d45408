# Free surfaces (docs/theory.md §3): Newtonian die swell against Tanner's values, conservation
# and power on the moved mesh, the shear-thinning trend, the iteration cap, the extrusion with a
# separating die land (leak, gap, adaptive force against the bilateral land), sensitivities on a
# moving shape, bad input.
set(FLOWFORM_PYTHON /usr/bin/python3)
add_test(NAME free_surface_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/free_surface_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/free_surface)
set_tests_properties(free_surface_checks PROPERTIES LABELS "regression")

# Orthogonal cutting with a free chip (docs/cutting.md): balances, Coulomb's F_t/F_c, the
# chip's dependence on its start at ν = 0, derivatives through the converged chip, bad input.
add_test(NAME cutting_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/cutting_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/cutting)
set_tests_properties(cutting_checks PROPERTIES LABELS "regression")
