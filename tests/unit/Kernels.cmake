# Material law, flow kernel (hand values, AD Jacobian vs FD, rigid motions) and the
# assembled problem (patch tests, exact solves, parallel = serial on 1 and 2 ranks).
flowform_unit_test(MaterialTest unit/MaterialTest.cpp)
# The Sellars–Tegart law and the material-law registry.
flowform_unit_test(SellarsTegartTest unit/SellarsTegartTest.cpp)
flowform_unit_test(HenselSpittelTest unit/HenselSpittelTest.cpp)
flowform_unit_test(FlowKernelTest unit/FlowKernelTest.cpp)
flowform_unit_test(FlowKernelDerivativeTest unit/FlowKernelDerivativeTest.cpp)
flowform_unit_test(AssemblyTest unit/AssemblyTest.cpp)
flowform_unit_test(AssemblyTest unit/AssemblyTest.cpp NP 2)
flowform_unit_test(AssemblyParallelTest unit/AssemblyParallelTest.cpp)
flowform_unit_test(AssemblyParallelTest unit/AssemblyParallelTest.cpp NP 2)
target_compile_definitions(AssemblyParallelTest PRIVATE FLOWFORM_SOURCE_DIR="${FLOWFORM_SOURCE_DIR}")
target_compile_definitions(AssemblyTest PRIVATE FLOWFORM_SOURCE_DIR="${FLOWFORM_SOURCE_DIR}")
# A rank that throws leaves the other waiting in a collective: fail instead of hanging.
set_tests_properties(AssemblyTest AssemblyTest_np2 AssemblyParallelTest AssemblyParallelTest_np2 PROPERTIES TIMEOUT 300)
# Moving the mesh nodes: refreshed geometry gives the residual of a fresh mesh (1 and 2 ranks).
flowform_unit_test(MovingMeshTest unit/MovingMeshTest.cpp)
flowform_unit_test(MovingMeshTest unit/MovingMeshTest.cpp NP 2)
# The dual linearizations of Newton (stress and slip): values unchanged, fresh = exact tangent,
# O(step) departure, bounds kept (docs/theory.md §9).
flowform_unit_test(NewtonDualTest unit/NewtonDualTest.cpp)
# A second field beside the flow (physics kernels as plug-ins): the flow's rows bitwise
# unchanged, a linear passive scalar exact (1 and 2 ranks).
flowform_unit_test(FieldKernelTest unit/FieldKernelTest.cpp)
flowform_unit_test(FieldKernelTest unit/FieldKernelTest.cpp NP 2)
set_tests_properties(FieldKernelTest FieldKernelTest_np2 PROPERTIES TIMEOUT 300)
# The energy balance's kernel (the Temperature field of Material/Thermal): its Jacobian against
# central differences (P1, Q1, plane, axisymmetric, diffusive and convective) and a linear T exact.
flowform_unit_test(CoupledFlowKernelTest unit/CoupledFlowKernelTest.cpp)
