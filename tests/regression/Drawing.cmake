# Wire drawing through a conical die (xml/drawing.xml, docs/drawing.md): the balances, Sachs's and
# the upper-bound drawing stresses, the rigid-plastic limit, the optimal angle, the dead zone and
# the total derivatives by ν and the die angle (drawing_checks.py).
add_test(NAME drawing_checks
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/drawing_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/drawing)
set_tests_properties(drawing_checks PROPERTIES LABELS "regression")
# The drawing geometry's own checks and the drawing responses' bad input.
flowform_exit_test(bad_input_drawing_exit_wider_than_entry CASE ../../../xml/drawing.xml
  SET "Mesh/Geo Parameters/R1=1.2"
  CONTAINS "R1 = 1.2 must be smaller than the entry radius")
flowform_exit_test(bad_input_redundant_work_without_entry CASE ../../../xml/drawing.xml
  SET "Responses/redundant_work/Entry Boundary="
  CONTAINS "Redundant Work Factor" "'Entry Boundary' is required")
flowform_exit_test(bad_input_redundant_work_entry_narrower CASE ../../../xml/drawing.xml
  SET "Responses/redundant_work/Entry Boundary=die_land"
  CONTAINS "Redundant Work Factor" "is not wider than 'outlet'")
flowform_exit_test(bad_input_redundant_work_nonpositive_flow_stress CASE ../../../xml/drawing.xml
  SET "Responses/redundant_work/Flow Stress=0"
  CONTAINS "Flow Stress" "> 0")
flowform_exit_test(bad_input_wall_pressure_off_a_wall CASE ../../../xml/drawing.xml
  SET "Responses/die_pressure/Boundary=outlet"
  CONTAINS "die_pressure" "outlet")
