# The friction sweep and its plot as docs/extrusion.md runs them (scripts/sweep_friction.py,
# scripts/plot_extrusion.py): the estimate and DDM derivative columns of sweep.csv are there and
# finite, and force_vs_nu.png draws the error bars and tangents; --fixed-mesh solves once without
# an estimate. Two adaptive runs with a 5 % target (one cycle each) and one fixed-mesh run
# (regression/sweep_script_checks.py).
add_test(NAME extrusion_sweep_script
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/regression/sweep_script_checks.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/sweep_script)
set_tests_properties(extrusion_sweep_script PROPERTIES LABELS "regression" TIMEOUT 300)
