# Rolling (docs/rolling.md): the strip nobody pushes under one roll, xml/rolling.xml and
# xml/rolling_flat.xml. Each test is one subcommand of regression/rolling_checks.py (the checks, their
# tolerances and the measured values are in its docstring); rolling_scene_perturbed expects the neutral point inside a 1° arc and must fail.
foreach(sub scene tension free_surfaces refined geometry shape bite bad_input)
  add_test(NAME rolling_${sub}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/rolling_checks.py ${sub}
                   $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/rolling/${sub})
  set_tests_properties(rolling_${sub} PROPERTIES LABELS "regression" TIMEOUT 300)
endforeach()
add_test(NAME rolling_scene_perturbed
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/rolling_checks.py scene
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/rolling/perturbed --perturbed)
set_tests_properties(rolling_scene_perturbed PROPERTIES LABELS "regression" TIMEOUT 300 WILL_FAIL TRUE)
