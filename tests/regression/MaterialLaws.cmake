# Material laws as plug-ins (physics/materials/): the Sellars–Tegart law's DDM parameter
# derivatives against central differences on its channel (sensitivity_checks.py
# sellars-tegart, tolerances there), a copy with a coarse step that must fail, and the bad
# inputs a law brings: an unknown Law, another law's parameter in the Material sublist or in
# Sensitivity/Parameters, a parameter out of its range — each exit 2 naming what is allowed.
add_test(NAME material_sellars_tegart_sensitivity
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/regression/sensitivity_checks.py sellars-tegart
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/material/sellars_tegart --step 5e-5)
set_tests_properties(material_sellars_tegart_sensitivity PROPERTIES LABELS "regression" TIMEOUT 300)
# The Hensel-Spittel law (xml/channel_hensel_spittel.xml): its eleven parameters, DDM against FD.
add_test(NAME material_hensel_spittel_sensitivity
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/regression/sensitivity_checks.py hensel-spittel
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/material/hensel_spittel)
set_tests_properties(material_hensel_spittel_sensitivity PROPERTIES LABELS "regression" TIMEOUT 300)
# The checker can fail: with δ = 5 % of each parameter the truncation error is far above 1e-5.
add_test(NAME material_sellars_tegart_coarse_step_fails
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/regression/sensitivity_checks.py sellars-tegart
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/material/coarse --step 0.05)
set_tests_properties(material_sellars_tegart_coarse_step_fails PROPERTIES LABELS "regression" WILL_FAIL TRUE TIMEOUT 300)

if(NOT COMMAND flowform_exit_test)
  return()  # no python3: BadInput.cmake said so
endif()
set(FLOWFORM_ST_CASE ../../../xml/channel_sellars_tegart.xml)  # relative to bad_input/
flowform_exit_test(bad_input_material_law_unknown CASE channel_small.xml
  SET "Material/Law=Johnson-Cook"
  CONTAINS "Material/Law" "'Johnson-Cook'" "'Power Law', 'Sellars-Tegart'")
flowform_exit_test(bad_input_material_parameter_of_other_law CASE channel_small.xml
  SET "Material/Law=Sellars-Tegart"
  CONTAINS "Material/Yield Stress is a parameter of material law 'Power Law'" "'Sellars-Tegart'"
           "'Activation Energy'")
flowform_exit_test(bad_input_sensitivity_parameter_of_other_law CASE channel_small.xml
  SET "Sensitivity/Parameters={Temperature}"
  CONTAINS "'Temperature' is a parameter of material law 'Sellars-Tegart'" "Power Law" "'Yield Stress'")
flowform_exit_test(bad_input_sensitivity_parameter_of_power_law CASE ${FLOWFORM_ST_CASE}
  SET "Sensitivity/Parameters={Yield Stress}"
  CONTAINS "'Yield Stress' is a parameter of material law 'Power Law'" "'Activation Energy'" "'Rate Factor'")
flowform_exit_test(bad_input_material_temperature_negative CASE ${FLOWFORM_ST_CASE}
  SET "Material/Temperature=-5.0"
  CONTAINS "Material" "Temperature" "> 0")
