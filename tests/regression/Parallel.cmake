# A whole run on 2 ranks equals the serial run (nonlinear channel, both element types).
foreach(cell Triangle Quadrilateral)
  add_test(NAME parallel_equals_serial_${cell}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/compare_runs.py
                   $<TARGET_FILE:flowform> ${MPIEXEC_EXECUTABLE} 2 ${FLOWFORM_SOURCE_DIR}/xml/channel.xml
                   ${CMAKE_CURRENT_BINARY_DIR}/parallel_${cell}
                   --set "Mesh/Element Type=${cell}" --set "Mesh/Geo Parameters/N=8")
  set_tests_properties(parallel_equals_serial_${cell} PROPERTIES LABELS "regression")
endforeach()
# With contact walls: the friction law couples wall neighbours across the partition, and the
# contact-status loop must take the same decisions on every rank.
add_test(NAME parallel_equals_serial_extrusion
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/compare_runs.py
                 $<TARGET_FILE:flowform> ${MPIEXEC_EXECUTABLE} 2 ${FLOWFORM_SOURCE_DIR}/xml/extrusion.xml
                 ${CMAKE_CURRENT_BINARY_DIR}/parallel_extrusion --set "Adaptivity/Enabled=false")
set_tests_properties(parallel_equals_serial_extrusion PROPERTIES LABELS "regression")
# Sensitivities on 2 ranks: ∂R/∂h assembled per partition (the friction couples wall
# neighbours across it), the DDM solve through the gathered direct solver; du/dh, dp/dh
# compared field by field.
add_test(NAME parallel_equals_serial_sensitivity
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/compare_runs.py
                 $<TARGET_FILE:flowform> ${MPIEXEC_EXECUTABLE} 2 ${FLOWFORM_SOURCE_DIR}/xml/extrusion.xml
                 ${CMAKE_CURRENT_BINARY_DIR}/parallel_sensitivity --set "Adaptivity/Enabled=false"
                 --set "Sensitivity/Parameters={Friction Coefficient, Yield Stress, Rate Exponent}")
set_tests_properties(parallel_equals_serial_sensitivity PROPERTIES LABELS "regression")
# The two-level error estimate on 2 ranks: the refined mesh is partitioned anew, the coarse
# solution and statuses carried over (replicated), the refined solve with contact.
add_test(NAME parallel_equals_serial_error_estimate
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/compare_runs.py
                 $<TARGET_FILE:flowform> ${MPIEXEC_EXECUTABLE} 2 ${FLOWFORM_SOURCE_DIR}/xml/extrusion.xml
                 ${CMAKE_CURRENT_BINARY_DIR}/parallel_error_estimate --set "Adaptivity/Enabled=false"
                 --set "Error Estimation/Method=Two-Level")
set_tests_properties(parallel_equals_serial_error_estimate PROPERTIES LABELS "regression" PROCESSORS 2)
# The Newton Step estimate (the default) on 2 ranks: the refined steps, the chord step and the
# settling test (collective response evaluations) with the refined mesh partitioned anew.
add_test(NAME parallel_equals_serial_newton_step_estimate
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/compare_runs.py
                 $<TARGET_FILE:flowform> ${MPIEXEC_EXECUTABLE} 2 ${FLOWFORM_SOURCE_DIR}/xml/extrusion.xml
                 ${CMAKE_CURRENT_BINARY_DIR}/parallel_newton_step_estimate --set "Adaptivity/Enabled=false"
                 --set "Error Estimation/Method=Newton Step")
set_tests_properties(parallel_equals_serial_newton_step_estimate PROPERTIES LABELS "regression" PROCESSORS 2)
# MUMPS factors the distributed matrix itself (no gather): np = 2 and np = 3 against np = 1,
# with contact (the status loop's decisions) and on the channel. The ranks factor with
# different pivot orders, so the runs agree to the round-off of the factorization, amplified
# by Newton: the same 1e-9 bound.
foreach(np 2 3)
  add_test(NAME parallel_mumps_np${np}_extrusion
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/compare_runs.py
                   $<TARGET_FILE:flowform> ${MPIEXEC_EXECUTABLE} ${np} ${FLOWFORM_SOURCE_DIR}/xml/extrusion.xml
                   ${CMAKE_CURRENT_BINARY_DIR}/parallel_mumps_np${np}_extrusion --set "Adaptivity/Enabled=false"
                   --set "Solver/Linear Solver/Type=MUMPS" --set "Mesh/Geo Parameters/h=0.2"
                   --set "Mesh/Geo Parameters/hc=0.05")
  add_test(NAME parallel_mumps_np${np}_channel
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/compare_runs.py
                   $<TARGET_FILE:flowform> ${MPIEXEC_EXECUTABLE} ${np} ${FLOWFORM_SOURCE_DIR}/xml/channel.xml
                   ${CMAKE_CURRENT_BINARY_DIR}/parallel_mumps_np${np}_channel
                   --set "Solver/Linear Solver/Type=MUMPS" --set "Mesh/Geo Parameters/N=8")
  set_tests_properties(parallel_mumps_np${np}_extrusion parallel_mumps_np${np}_channel
                       PROPERTIES LABELS "regression" PROCESSORS 2)
endforeach()
# Free surfaces on 2 ranks: the surface update and the mesh motion run on the replicated mesh
# and must move every rank's copy the same way; the flow re-solves are distributed. The die
# swell (a Free Surface group) and the separating die land (a contact wall's released run), the
# latter with the total derivative through its shape (surface moves, distributed assemblies).
# flowform_parallel_equals_serial(NAME CASE [--set P=V ...]): xml/CASE on 2 ranks against 1.
function(flowform_parallel_equals_serial name case)
  add_test(NAME parallel_equals_serial_${name}
           COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/compare_runs.py
                   $<TARGET_FILE:flowform> ${MPIEXEC_EXECUTABLE} 2 ${FLOWFORM_SOURCE_DIR}/xml/${case}
                   ${CMAKE_CURRENT_BINARY_DIR}/parallel_${name} ${ARGN})
  set_tests_properties(parallel_equals_serial_${name} PROPERTIES LABELS "regression" PROCESSORS 2)
endfunction()
flowform_parallel_equals_serial(die_swell die_swell.xml)
flowform_parallel_equals_serial(separation extrusion_separation.xml --set "Adaptivity/Enabled=false"
                                --set "Sensitivity/Parameters={Friction Coefficient}")
# The cutting scene's free chip: two free surfaces meeting a contact wall's released run, the
# outlet held parallel to the rake (a rotated Dirichlet condition) until the surfaces converge,
# then released and the loop goes on with Anderson's history; a self-deciding separation node.
# The loop's ~70 re-solves amplify the round-off of the assembly's summation order, which on 2
# ranks is not repeatable from run to run (two np = 2 runs: F_c 1.6e-13 apart): over 7 runs
# (2026-11-25) the fields agreed to 2e-10 ... 3e-9 of their largest (strain rate, viscosity;
# velocity ≤ 6e-12, node positions ≤ 2e-12), the contact statuses exactly. Tolerance 1e-7: 30×
# the largest measured, 10³ below the loop's own move tolerance (1e-4). 45–55 s for both runs.
flowform_parallel_equals_serial(cutting_free_chip cutting.xml --tol 1e-7 --set "Error Estimation/Method=None"
                                --set "Boundary Conditions/chip_outlet/Release After Free Surfaces=true")
# Rolling: the Rigid Inflow's balance (its force sums reduced over the ranks, ~10 re-solves) and the
# Neutral Angle's per-node slip gathered from the owners, with the bordered DDM.
flowform_parallel_equals_serial(rolling rolling_flat.xml --set "Error Estimation/Method=None")
# The shipped rolling case: both strip surfaces free, the entry one sliding the roll's nodes, the
# total derivatives by ν through them and U (dφ/dR, dφ/dh1 left out: their mesh partials are
# differences over node moves of 10⁻⁹ of the mesh, whose round-off depends on the ranks' summation
# order, 10⁻⁶–10⁻³ apart between 1 and 2 ranks). Fields agree to ≤ 3e-10 (measured, dp/dν the
# largest; default --tol 1e-9). The total derivatives: 10⁻⁸–7.5·10⁻⁷ apart for the forces, powers and
# the neutral angle, 2–4·10⁻⁶ for the flux through the roll (its penalty's leak, 5·10⁻⁵ of the
# throughput: a cancellation), hence --tol-shape 1e-5. Left out, as zero by construction so that
# their derivatives are round-off: inlet_power (U × the inflow's imbalance, zero to the balance's
# tolerance) and the fluxes through the free strip surfaces (zero to the loop's flow-angle
# tolerance; 3·10⁻⁶ and 2·10⁻⁵ apart in two runs of the entry surface's).
flowform_parallel_equals_serial(rolling_free rolling.xml --tol-shape 1e-5 --ignore inlet_power
                                --ignore entry_surface_flux --ignore exit_surface_flux
                                --set "Error Estimation/Method=None" --set "Sensitivity/Parameters={Friction Coefficient}")
# The Temperature field on 2 ranks: its rows, the prescribed temperatures (owned nodes only) and
# the Heat Flow reactions summed over the ranks.
flowform_parallel_equals_serial(thermal_channel thermal_channel.xml)
# The temperature-dependent law on 2 ranks: the flow kernel reading each cell's temperature, the
# contact walls' penalty scales from the cells' states at their temperatures.
flowform_parallel_equals_serial(hot_extrusion hot_extrusion.xml)
# Wire drawing: a free surface that ends on a contact wall and the Wall Pressure summed over the
# owners; the optimizer on 2 ranks (ROL runs on every rank on replicated vectors, each solve
# distributed: the same designs, 13 solves either way). Fields and responses agree to ≤ 6e-11;
# the total derivatives through the surface differ by up to 5.4e-6 (the penalty power's, 5e-5 of
# the drawing power: the shape derivative's partials are central differences at 1e-6 of the
# surface length, whose round-off (~1e-10 of their terms) is large against so small a derivative;
# docs/theory.md §3.5): their tolerance 3e-5 (--tol-shape). Without the die-angle derivative: its frozen field dp/dalpha
# differs by 3e-4 (differences in node positions at 1e-9 of the mesh size), a property of the
# shape derivative's partials that sensitivity_shape checks serially.
flowform_parallel_equals_serial(drawing drawing.xml --tol-shape 3e-5 --set "Sensitivity/Parameters={Friction Coefficient}")
flowform_parallel_equals_serial(drawing_identify_friction drawing_identify_friction.xml --tol-shape 3e-5)
# The adjoint on 2 ranks: each rank's response gradient by its own dofs (ghosts exported with ADD to
# their owners), the reactions' part by J_uncᵀ, the transposed solve distributed; inside the
# optimizer with a friction field (the same solves and designs either way).
flowform_parallel_equals_serial(extrusion_identify_friction_field extrusion_identify_friction_field.xml)
# The constrained optimizer on 2 ranks: every rank runs the SQP on the same (reduced) responses and
# derivatives, so the ranks take the same steps; the same solves and design as on one.
flowform_parallel_equals_serial(hot_extrusion_window hot_extrusion_window.xml)
flowform_parallel_equals_serial(adjoint_extrusion extrusion.xml --set "Adaptivity/Enabled=false"
                                --set "Sensitivity/Method=Adjoint"
                                --set "Sensitivity/Parameters={Friction Coefficient:container, Yield Stress}"
                                --set "Responses/plastic_power/Type=Plastic Power"
                                --set "Responses/exit_speed/Type=Point Value" --set "Responses/exit_speed/Field=Velocity X"
                                --set "Responses/exit_speed/X=1.2" --set "Responses/exit_speed/Y=0.05")
