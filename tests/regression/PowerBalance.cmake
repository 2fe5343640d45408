# The discrete power balance closes to solver tolerance (power_balance.py), with friction
# (Coulomb ν = 0.1, plane strain), without, axisymmetric, and on the mesh a free surface moved
# (the separating die land, docs/theory.md §3.4: the traction-free surface adds no power); and with a
# moving tool (the container translating at the ram speed, Coulomb ν = 0.1: its Tool Power enters).
foreach(variant coulomb frictionless axisymmetric separating_land moving_container)
  set(case ${FLOWFORM_SOURCE_DIR}/xml/extrusion.xml)
  set(extra --set "Adaptivity/Enabled=false")  # the scene's own mesh, solved once
  if(variant STREQUAL "frictionless")
    list(APPEND extra --set "Boundary Conditions/container/Friction Coefficient=0.0"
              --set "Boundary Conditions/die_face/Friction Coefficient=0.0"
              --set "Boundary Conditions/die_land/Friction Coefficient=0.0")
  elseif(variant STREQUAL "axisymmetric")
    set(case ${FLOWFORM_SOURCE_DIR}/xml/extrusion_axisym.xml)
  elseif(variant STREQUAL "moving_container")
    list(APPEND extra --moving-wall container --set "Boundary Conditions/container/Tool Motion=Translation"
              --set "Boundary Conditions/container/Tool Velocity X=1.0")
  elseif(variant STREQUAL "separating_land")
    set(case ${FLOWFORM_SOURCE_DIR}/xml/extrusion_separation.xml)
  endif()
  add_test(NAME power_balance_${variant}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/power_balance.py
                   $<TARGET_FILE:flowform> ${case} ${CMAKE_CURRENT_BINARY_DIR}/power_${variant} ram ${extra})
  set_tests_properties(power_balance_${variant} PROPERTIES LABELS "regression")
endforeach()
