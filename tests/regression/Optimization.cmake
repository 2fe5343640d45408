# Design and inverse problems on ROL (docs/optimization.md): the die angle of least drawing force
# against an independent sweep and upper-bound theory; the friction coefficient from measurements
# with its Gauss-Newton interval (optimization_checks.py).
add_test(NAME optimization_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/optimization_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/optimization --part drawing)
set_tests_properties(optimization_checks PROPERTIES LABELS "regression")
# The roll's friction coefficient from a roll force and a forward slip (the rolling scene).
add_test(NAME optimization_checks_rolling
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/optimization_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/optimization --part rolling)
set_tests_properties(optimization_checks_rolling PROPERTIES LABELS "regression")
# A bad Optimization sublist: exit 2 before any solve, naming the entry.
set(FLOWFORM_OPT_CASE ../../../xml/drawing_identify_friction.xml)
flowform_exit_test(bad_input_optimization_bounds_count CASE ${FLOWFORM_OPT_CASE}
  SET "Optimization/Lower Bounds={0.0, 0.1}"
  CONTAINS "Optimization/Lower Bounds, Upper Bounds" "one each per design parameter")
flowform_exit_test(bad_input_optimization_bounds_crossed CASE ${FLOWFORM_OPT_CASE}
  SET "Optimization/Lower Bounds={0.3}" "Optimization/Upper Bounds={0.1}"
  CONTAINS "'Friction Coefficient' needs finite bounds, lower < upper")
flowform_exit_test(bad_input_optimization_start_outside_bounds CASE ${FLOWFORM_OPT_CASE}
  SET "Optimization/Lower Bounds={0.06}"
  CONTAINS "starts at the case's value" "outside its bounds")
flowform_exit_test(bad_input_optimization_objective_and_misfit CASE ${FLOWFORM_OPT_CASE}
  SET "Optimization/Objective=drawing_force"
  CONTAINS "give either an Objective" "not both")
flowform_exit_test(bad_input_optimization_no_objective CASE ${FLOWFORM_OPT_CASE}
  SET "Optimization/Measured Responses={}" "Optimization/Measured Values={}" "Optimization/Measurement Errors={}"
  CONTAINS "give either an Objective" "not neither")
flowform_exit_test(bad_input_optimization_measured_count CASE ${FLOWFORM_OPT_CASE}
  SET "Optimization/Measured Values={0.91}"
  CONTAINS "Optimization/Measured Values: one per Measured Response")
flowform_exit_test(bad_input_optimization_measurement_error CASE ${FLOWFORM_OPT_CASE}
  SET "Optimization/Measurement Errors={0.005, 0}"
  CONTAINS "'die_pressure' needs a finite value and an error > 0")
flowform_exit_test(bad_input_optimization_unknown_response CASE ${FLOWFORM_OPT_CASE}
  SET "Optimization/Measured Responses={drawing_force, ram_force}"
  CONTAINS "'ram_force' is not one of the case's Responses")
flowform_exit_test(bad_input_optimization_design_not_in_case CASE ${FLOWFORM_OPT_CASE}
  SET "Optimization/Design Parameters={Geo Parameter:Ld}"
  CONTAINS "Optimization/Design Parameters: 'Geo Parameter:Ld'" "does not set Mesh/Geo Parameters/Ld")
flowform_exit_test(bad_input_optimization_with_adaptivity CASE ${FLOWFORM_OPT_CASE}
  SET "Adaptivity/Responses={drawing_force}"
  CONTAINS "Optimization with Adaptivity")
flowform_exit_test(bad_input_reference_topology_unknown_name CASE ../../../xml/drawing.xml
  SET "Mesh/Reference Geo Parameters/beta=3"
  CONTAINS "beta")
# Constraints (responses with bounds, the trust-region SQP): the hot extrusion's largest ram speed
# under an exit-temperature and a force limit, and the best point of its extrusion window, against
# independent runs and the optimum's difference by the limit (constrained_optimization_checks.py).
add_test(NAME constrained_optimization_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/constrained_optimization_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/constrained_optimization)
set_tests_properties(constrained_optimization_checks PROPERTIES LABELS "regression")
# A bad constraint: exit 2 before any solve, naming the entry.
set(FLOWFORM_CONSTRAINED_CASE ../../../xml/hot_extrusion_max_speed.xml)
flowform_exit_test(bad_input_optimization_constraint_unknown_response CASE ${FLOWFORM_CONSTRAINED_CASE}
  SET "Optimization/Constrained Responses={exit_temperature, drawing_force}"
  CONTAINS "'drawing_force' is not one of the case's Responses")
flowform_exit_test(bad_input_optimization_constraint_bounds_count CASE ${FLOWFORM_CONSTRAINED_CASE}
  SET "Optimization/Constraint Upper Bounds={740.0}"
  CONTAINS "Optimization/Constraint Upper Bounds: one per Constrained Response (2) or none, given 1")
flowform_exit_test(bad_input_optimization_constraint_no_bound CASE ${FLOWFORM_CONSTRAINED_CASE}
  SET "Optimization/Constraint Upper Bounds={}"
  CONTAINS "'exit_temperature' has neither a lower nor an upper bound")
flowform_exit_test(bad_input_optimization_constraint_bounds_crossed CASE ${FLOWFORM_CONSTRAINED_CASE}
  SET "Optimization/Constraint Lower Bounds={750.0, 0.0}"
  CONTAINS "the constraint on 'exit_temperature' needs its lower bound" "below its upper bound")
flowform_exit_test(bad_input_optimization_constraint_named_twice CASE ${FLOWFORM_CONSTRAINED_CASE}
  SET "Optimization/Constrained Responses={exit_temperature, exit_temperature}"
  CONTAINS "'exit_temperature' is named twice")
