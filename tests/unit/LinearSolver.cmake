# The direct solver: both orderings, serial and gathered to rank 0 (2 ranks).
flowform_unit_test(LinearSolverTest unit/LinearSolverTest.cpp)
flowform_unit_test(LinearSolverTest unit/LinearSolverTest.cpp NP 2)
set_tests_properties(LinearSolverTest LinearSolverTest_np2 PROPERTIES TIMEOUT 120)
