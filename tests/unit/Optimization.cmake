# The constrained optimizer's subproblem: the dense interior-point QP against hand solutions.
flowform_unit_test(DenseQpTest unit/DenseQpTest.cpp)
