# The stress battery of the nonlinear solve (tests/regression/stress_checks.py): cases at the
# edges of the parameter ranges; every one must converge (exit 0) with finite responses.
# channel: γ = 1e-3, 1e3; e0 = 1e-6, 1e-2; n = 1, 100; the n = 7, e0 = 1e-5 stall case.
# extrusion (h = 0.2): σ0 = 0, n = 100, e0 = 1e-5, κ_t = 1e2 ... 1e8, ν = 2, 5; κ_t = 100 with
# ν = 0.2 on hc = 0.005; the channel at γ = 1e6.
# rolling: xml/rolling_flat.xml at ν = 0.1, 0.5, 2, reductions 5 %, 40 %, R/h0 = 5, 20, 50, back tension 0.2,
# front tension 0.3 (docs/rolling.md §9); rolling_free (label slow): the same on xml/rolling.xml as
# shipped, both strip surfaces free.
# grid (label slow): the channel over γ ∈ {1e-3, 1, 1e3, 1e6} × e0 ∈ {1e-6, 1e-4, 1e-2} ×
# n ∈ {1, 5, 100}; the extrusion (plane, axisymmetric) over ν ∈ {0, 0.5, 1, 2, 5} × κ_t ∈ {10, 1e4, 1e8}.
foreach(group channel extrusion rolling rolling_free grid)
  add_test(NAME stress_${group}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/stress_checks.py ${group}
                   $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/stress/${group})
  set_tests_properties(stress_${group} PROPERTIES LABELS "regression" TIMEOUT 900)
endforeach()
set_tests_properties(stress_grid stress_rolling_free PROPERTIES LABELS "slow" TIMEOUT 3600)

# Friction far above the shear strength (Coulomb ν = 1, 2 on every wall of the extrusion;
# tests/regression/high_friction_checks.py, docs/contact.md): a start carried from another mesh
# that fails gives way to the mesh's own start. two_level: the refined solve of the estimate at
# ν = 2 equals a run from scratch on the refined mesh; adaptive (slow): the shipped adaptivity at
# ν = 1 and 2 converges and meets its target.
foreach(part two_level adaptive)
  add_test(NAME high_friction_${part}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/high_friction_checks.py ${part}
                   $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/high_friction/${part})
  set_tests_properties(high_friction_${part} PROPERTIES LABELS "regression" TIMEOUT 900)
endforeach()
set_tests_properties(high_friction_adaptive PROPERTIES LABELS "slow" TIMEOUT 3600)
