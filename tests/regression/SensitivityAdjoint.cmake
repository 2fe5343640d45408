# Adjoint sensitivities and friction fields (docs/sensitivity.md "Adjoint", docs/contact.md
# "Friction fields"): the adjoint equal to the direct differentiation to round-off on scenes with
# responses of every kind; a friction field's derivatives against finite differences and against
# the uniform ν (adjoint_checks.py; tolerances justified there).
foreach(sub agree field identify)
  add_test(NAME adjoint_${sub}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/adjoint_checks.py ${sub}
                   $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/adjoint/${sub})
  set_tests_properties(adjoint_${sub} PROPERTIES LABELS "regression" TIMEOUT 600)
endforeach()
# Bad input: exit 2 before any solve, naming the entry.
set(FLOWFORM_FIELD_SETS "Adaptivity/Enabled=false" "Boundary Conditions/container/Friction Field={0.1, 0.2, 0.3}")
flowform_exit_test(bad_input_friction_field_one_value CASE ../../../xml/extrusion.xml
  SET "Boundary Conditions/container/Friction Field={0.1}"
  CONTAINS "Boundary Conditions/container/Friction Field: needs at least 2 values")
flowform_exit_test(bad_input_friction_field_negative CASE ../../../xml/extrusion.xml
  SET "Boundary Conditions/container/Friction Field={0.1, -0.2}"
  CONTAINS "Friction Field: every value must be a finite number >= 0")
flowform_exit_test(bad_input_friction_field_tresca CASE ../../../xml/extrusion.xml
  SET "Boundary Conditions/container/Friction Law=Tresca" "Boundary Conditions/container/Shear Factor=0.5"
      "Boundary Conditions/container/Friction Field={0.1, 0.2}"
  CONTAINS "Friction Law = Tresca has no friction coefficient")
flowform_exit_test(bad_input_friction_field_station CASE ../../../xml/extrusion.xml
  SET ${FLOWFORM_FIELD_SETS} "Sensitivity/Parameters={Friction Field:container/3}"
  CONTAINS "the station must be a whole number from 0 to 2")
flowform_exit_test(bad_input_friction_field_no_field CASE ../../../xml/extrusion.xml
  SET ${FLOWFORM_FIELD_SETS} "Sensitivity/Parameters={Friction Field:die_land/0}"
  CONTAINS "'die_land' is not a contact wall with a Friction Field")
flowform_exit_test(bad_input_friction_coefficient_on_field CASE ../../../xml/extrusion.xml
  SET ${FLOWFORM_FIELD_SETS} "Sensitivity/Parameters={Friction Coefficient}"
  CONTAINS "wall 'container' has a Friction Field, not one ν")
flowform_exit_test(bad_input_adjoint_rigid_inflow CASE ../../../xml/rolling.xml
  SET "Sensitivity/Parameters={Friction Coefficient}" "Sensitivity/Method=Adjoint"
  CONTAINS "Sensitivity/Method: Adjoint does not handle a Rigid Inflow")
flowform_exit_test(bad_input_adjoint_total_shape CASE ../../../xml/die_swell.xml
  SET "Sensitivity/Parameters={Yield Stress}" "Sensitivity/Method=Adjoint"
  CONTAINS "Adjoint gives no dq/dh" "Shape Derivative = Frozen")
flowform_exit_test(bad_input_adjoint_last_newton_jacobian CASE ../../../xml/channel.xml
  SET "Sensitivity/Parameters={Yield Stress}" "Sensitivity/Method=Adjoint" "Sensitivity/Jacobian=Last Newton Iterate"
  CONTAINS "'Last Newton Iterate' is for Method = Direct")
flowform_exit_test(bad_input_sensitivity_response_not_differentiable CASE ../../../xml/extrusion.xml
  SET "Sensitivity/Parameters={Friction Coefficient}" "Sensitivity/Responses={dead_zone}"
  CONTAINS "Sensitivity/Responses: 'dead_zone' is not a differentiable response")
