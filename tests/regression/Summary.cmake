# What a run costs and reports, read from summary.json.
# A Newtonian case (n = 1, σ0 = 0) is linear: one factorization, one solve, no Newton.
add_test(NAME newtonian_costs_one_solve
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_summary.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR}/xml/channel.xml ${CMAKE_CURRENT_BINARY_DIR}/newtonian
                 --set "Material/Rate Exponent=1" --set "Material/Yield Stress=0"
                 -- converged=true linear_problem=true newton_iterations=0
                    linear_solver.factorizations=1 linear_solver.solves=1)
set_tests_properties(newtonian_costs_one_solve PROPERTIES LABELS "regression")
# ... but not with a Coulomb wall (p⁺ and the sticking bound): Newton, not one linear solve (which
# left |F| = 0.148 here: exit 3). The extrusion with n = 1, σ0 = 0 and its container moving.
add_test(NAME newtonian_with_coulomb_wall_uses_newton
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_summary.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR}/xml/extrusion.xml ${CMAKE_CURRENT_BINARY_DIR}/newtonian_coulomb
                 --set "Adaptivity/Enabled=false" --set "Material/Rate Exponent=1" --set "Material/Yield Stress=0"
                 --set "Boundary Conditions/container/Tool Motion=Translation"
                 --set "Boundary Conditions/container/Tool Velocity X=1.0"
                 -- converged=true linear_problem=false exit_status=0)
set_tests_properties(newtonian_with_coulomb_wall_uses_newton PROPERTIES LABELS "regression")
# n = 40 (the cutting scene's exponent, docs/theory.md §6.3) is reached by continuation, and the
# result says how.
add_test(NAME continuation_reaches_n40
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_summary.py
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR}/xml/channel.xml ${CMAKE_CURRENT_BINARY_DIR}/n40
                 --set "Material/Rate Exponent=40" --set "Mesh/Geo Parameters/N=8"
                 -- converged=true linear_problem=false parameters.Material.Rate\ Exponent=40.0)
set_tests_properties(continuation_reaches_n40 PROPERTIES LABELS "regression")
# Not converged: exit status 3, results still written and flagged (docs/theory.md §5). One Newton
# iteration per stage and no room to halve the continuation step cannot converge n = 5.
add_test(NAME not_converged_exits_3
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_summary.py --expect-exit 3
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR}/xml/channel.xml ${CMAKE_CURRENT_BINARY_DIR}/not_converged
                 --set "Solver/Max Newton Iterations=1" --set "Solver/Continuation/Minimum Step=0.2"
                 -- converged=false exit_status=3)
set_tests_properties(not_converged_exits_3 PROPERTIES LABELS "regression")
# A singular linear system is reported as not converged, exit 3 with results written —
# never an abort. γ = 1e200 makes the Newtonian predictor's μ = 1/(3γ) vanish next to the
# pressure stabilization (h²/μ): its factorization fails from every start (at γ = 1e100 the
# run converges).
add_test(NAME singular_matrix_exits_3
         COMMAND ${FLOWFORM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_summary.py --expect-exit 3
                 $<TARGET_FILE:flowform> ${FLOWFORM_SOURCE_DIR}/xml/extrusion.xml ${CMAKE_CURRENT_BINARY_DIR}/singular
                 --set "Adaptivity/Enabled=false"
                 --set "Material/Rate Constant=1e200" --set "Material/Rate Exponent=20"
                 --set "Boundary Conditions/container/Friction Coefficient=0.0"
                 --set "Boundary Conditions/die_face/Friction Coefficient=0.0"
                 --set "Boundary Conditions/die_land/Friction Coefficient=0.0"
                 -- converged=false exit_status=3)
set_tests_properties(singular_matrix_exits_3 PROPERTIES LABELS "regression")
