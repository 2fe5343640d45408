# The Temperature field (Material/Thermal, docs/theory.md §10): the exact fully developed channel
# with plastic heating (orders, energy balance; thermal_channel_checks.py), its adiabatic limit, a case without the
# sublist has no temperature unknowns, and the thermal input errors (exit 2, nothing written).
foreach(what convergence adiabatic transfer isothermal)
  add_test(NAME thermal_channel_${what}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/thermal_channel_checks.py ${what}
                   $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/thermal_${what})
  set_tests_properties(thermal_channel_${what} PROPERTIES LABELS "regression")
endforeach()

flowform_exit_test(bad_input_temperature_without_thermal CASE channel_small.xml
  SET "Boundary Conditions/top/Temperature=1"
  CONTAINS "Boundary Conditions/top" "Material/Thermal")
flowform_exit_test(bad_input_thermal_conductivity CASE channel_small.xml
  SET "Material/Thermal/Conductivity=-1"
  CONTAINS "Material/Thermal/Conductivity")
flowform_exit_test(bad_input_heat_flow_without_thermal CASE channel_small.xml
  SET "Responses/q/Type=Heat Flow" "Responses/q/Boundary=top"
  CONTAINS "Responses/q" "Material/Thermal")
flowform_exit_test(bad_input_conflicting_temperatures CASE channel_small.xml
  SET "Material/Thermal/Conductivity=1" "Boundary Conditions/top/Temperature=1" "Boundary Conditions/inlet/Temperature=2"
  CONTAINS "'top' and 'inlet'" "different temperatures")
# Hot extrusion of AA6063 in real units: the isothermal limit (k = 1e9), thermal softening, the
# adiabatic bound and the energy balance (hot_extrusion_checks.py).
add_test(NAME hot_extrusion_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/hot_extrusion_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/hot_extrusion)
set_tests_properties(hot_extrusion_checks PROPERTIES LABELS "regression")
flowform_exit_test(bad_input_heat_transfer_without_ambient CASE channel_small.xml
  SET "Material/Thermal/Conductivity=1" "Boundary Conditions/top/Heat Transfer Coefficient=2"
  CONTAINS "Boundary Conditions/top" "Ambient Temperature")
flowform_exit_test(bad_input_heat_transfer_and_temperature CASE channel_small.xml
  SET "Material/Thermal/Conductivity=1" "Boundary Conditions/top/Heat Transfer Coefficient=2"
      "Boundary Conditions/top/Ambient Temperature=1" "Boundary Conditions/top/Temperature=1"
  CONTAINS "Boundary Conditions/top" "both a prescribed 'Temperature' and a 'Heat Transfer Coefficient'")
flowform_exit_test(bad_input_tool_temperature_off_a_wall CASE channel_small.xml
  SET "Material/Thermal/Conductivity=1" "Boundary Conditions/top/Heat Transfer Coefficient=2"
      "Boundary Conditions/top/Tool Temperature=1"
  CONTAINS "Boundary Conditions/top/Tool Temperature" "Ambient Temperature")
flowform_exit_test(bad_input_heat_transfer_negative CASE channel_small.xml
  SET "Material/Thermal/Conductivity=1" "Boundary Conditions/top/Heat Transfer Coefficient=-2"
      "Boundary Conditions/top/Ambient Temperature=1"
  CONTAINS "Heat Transfer Coefficient")
# The decision: the largest ram speed for an exit temperature and a ram force (scripts/extrusion_limits.py).
add_test(NAME extrusion_limits_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/extrusion_limits_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/extrusion_limits)
set_tests_properties(extrusion_limits_checks PROPERTIES LABELS "regression")
flowform_exit_test(bad_input_sensitivity_unknown_boundary_value CASE channel_small.xml
  SET "Sensitivity/Parameters={Boundary Value:top/Temperature}"
  CONTAINS "Boundary Value:top/Temperature" "Boundary Value:inlet/Velocity Y")
flowform_exit_test(bad_input_sensitivity_law_temperature_with_field CASE ../../../xml/hot_extrusion.xml
  SET "Sensitivity/Parameters={Temperature}"
  CONTAINS "Sensitivity/Parameters: 'Temperature'" "Boundary Value:")
# The round bar (xml/hot_extrusion_axisym.xml): the same checks.
add_test(NAME hot_extrusion_axisym_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/hot_extrusion_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/hot_extrusion_axisym
                 hot_extrusion_axisym.xml)
set_tests_properties(hot_extrusion_axisym_checks PROPERTIES LABELS "regression")
# A thermocouple (Point Value) off the mesh, or reading a temperature the case does not have; a
# friction heat fraction off a contact wall, or without the temperature field.
flowform_exit_test(bad_input_point_value_outside_mesh CASE channel_small.xml
  SET "Responses/probe/Type=Point Value" "Responses/probe/Field=Pressure" "Responses/probe/X=100"
  CONTAINS "Responses/probe/X, Y" "lies outside mesh")
flowform_exit_test(bad_input_point_value_temperature_without_field CASE channel_small.xml
  SET "Responses/probe/Type=Point Value" "Responses/probe/X=0.5" "Responses/probe/Y=0.5"
  CONTAINS "Responses/probe" "needs a temperature field")
flowform_exit_test(bad_input_friction_heat_off_a_wall CASE channel_small.xml
  SET "Material/Thermal/Conductivity=1" "Boundary Conditions/top/Friction Heat Fraction=0.5"
  CONTAINS "Boundary Conditions/top/Friction Heat Fraction" "only a Contact Wall")
flowform_exit_test(bad_input_friction_heat_without_field CASE channel_small.xml
  SET "Boundary Conditions/top/Friction Heat Fraction=0.5"
  CONTAINS "Boundary Conditions/top" "no temperature field")
# A thermal property as a sensitivity parameter in a case without the field, or one that is none.
flowform_exit_test(bad_input_sensitivity_thermal_without_field CASE channel_small.xml
  SET "Sensitivity/Parameters={Thermal:Conductivity}"
  CONTAINS "Thermal:Conductivity" "add a Material/Thermal sublist")
flowform_exit_test(bad_input_sensitivity_thermal_unknown CASE channel_small.xml
  SET "Material/Thermal/Conductivity=1" "Sensitivity/Parameters={Thermal:Emissivity}"
  CONTAINS "Thermal:Emissivity" "Conductivity, Density, Specific Heat, Heat Fraction")
# Heat transfer on a moving free surface: the die-swell extrudate cooling in air (one-way coupling:
# the flow is the isothermal one; the energy balance closes) (cooling_extrudate_checks.py).
add_test(NAME cooling_extrudate_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/cooling_extrudate_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/cooling_extrudate)
set_tests_properties(cooling_extrudate_checks PROPERTIES LABELS "regression")
# A friction heat fraction outside [0, 1] (the entry's validator); Hensel-Spittel's constants that
# make the flow stress fall with the rate, or need theta > 0 where the law's temperature is below 0 °C.
flowform_exit_test(bad_input_friction_heat_out_of_range CASE ../../../xml/hot_extrusion.xml
  SET "Boundary Conditions/container/Friction Heat Fraction=1.5"
  CONTAINS "Friction Heat Fraction")
flowform_exit_test(bad_input_hensel_spittel_rate_exponent CASE ../../../xml/channel_hensel_spittel.xml
  SET "Material/m8=-0.001"
  CONTAINS "Material (Hensel-Spittel)" "m3 + m8")
flowform_exit_test(bad_input_hensel_spittel_cold_m9 CASE ../../../xml/channel_hensel_spittel.xml
  SET "Material/Temperature=250"
  CONTAINS "Material (Hensel-Spittel)" "273.15")
# The Strain field (Material/Strain Field, docs/theory.md §1.1): the exact channel strain, the drawn
# wire's strain against its plastic work, and the hot Hensel–Spittel extrusion (one-way limit,
# uniform-strain bounds, DDM against FD; strain_field_checks.py) — and its input errors.
foreach(what channel drawing hot)
  add_test(NAME strain_field_${what}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/strain_field_checks.py ${what}
                   $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/strain_field_${what})
  set_tests_properties(strain_field_${what} PROPERTIES LABELS "regression" TIMEOUT 300)
endforeach()
flowform_exit_test(bad_input_strain_without_field CASE channel_small.xml
  SET "Boundary Conditions/inlet/Strain=0"
  CONTAINS "Boundary Conditions/inlet/Strain" "Material/Strain Field")
flowform_exit_test(bad_input_strain_field_without_inflow CASE channel_small.xml
  SET "Material/Strain Field/Minimum Strain=0.05"
  CONTAINS "Material/Strain Field" "'Strain'" "inflow")
flowform_exit_test(bad_input_strain_field_minimum CASE channel_small.xml
  SET "Material/Strain Field/Minimum Strain=0" "Boundary Conditions/inlet/Strain=0"
  CONTAINS "Material/Strain Field/Minimum Strain")
flowform_exit_test(bad_input_strain_field_maximum CASE channel_small.xml
  SET "Material/Strain Field/Maximum Strain=0.01" "Boundary Conditions/inlet/Strain=0"
  CONTAINS "Material/Strain Field/Maximum Strain" "Minimum Strain")
flowform_exit_test(bad_input_mean_strain_without_field CASE channel_small.xml
  SET "Responses/s/Type=Mean Strain" "Responses/s/Boundary=outlet"
  CONTAINS "Responses/s" "strain field" "Material/Strain Field")
flowform_exit_test(bad_input_sensitivity_law_strain_with_field CASE ../../../xml/hot_extrusion_hensel_spittel.xml
  SET "Sensitivity/Parameters={Strain}"
  CONTAINS "Sensitivity/Parameters: 'Strain'" "Boundary Value:<inflow group>/Strain")
