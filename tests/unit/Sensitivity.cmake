# ∂R/∂h of the assembled problem against finite differences (every parameter, contact walls
# in stick, slip and tension, P1/Q1, plane/axisymmetric), the tangent evaluation, the
# parameter names; on 1 and 2 ranks.
flowform_unit_test(SensitivityTest unit/SensitivityTest.cpp)
flowform_unit_test(SensitivityTest unit/SensitivityTest.cpp NP 2)
set_tests_properties(SensitivityTest SensitivityTest_np2 PROPERTIES TIMEOUT 300)
target_compile_definitions(SensitivityTest PRIVATE FLOWFORM_SOURCE_DIR="${FLOWFORM_SOURCE_DIR}")
