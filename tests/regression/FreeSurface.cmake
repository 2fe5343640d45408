# Free surfaces (docs/theory.md §3): Newtonian die swell against Tanner's values, conservation
# and power on the moved mesh, the shear-thinning trend, the iteration cap, the extrusion with a
# separating die land (leak, gap, adaptive force against the bilateral land), sensitivities on a
# moving shape, bad input.
add_test(NAME free_surface_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/free_surface_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/free_surface)
set_tests_properties(free_surface_checks PROPERTIES LABELS "regression")

# Orthogonal cutting with a free chip (docs/cutting.md). The scene as shipped — balances,
# Coulomb's F_t/F_c, the shear plane, derivatives through the converged chip against FD, the
# estimate, bad input, plots — in the default run, and the derivatives by the rake angle against
# the finite-difference check (cutting_rake_angle, 1 min); the other members of the chip family,
# the rake, the free chip and the stalling case (about 12 min more) under the slow label.
add_test(NAME cutting_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/cutting_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/cutting --part shipped)
set_tests_properties(cutting_checks PROPERTIES LABELS "regression")
add_test(NAME cutting_rake_angle
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/cutting_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/cutting --part rake)
set_tests_properties(cutting_rake_angle PROPERTIES LABELS "regression")
add_test(NAME cutting_variants
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/cutting_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/cutting --part variants)
set_tests_properties(cutting_variants PROPERTIES LABELS "regression;slow")
