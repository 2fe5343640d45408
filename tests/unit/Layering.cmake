# The layering rule (scripts/check_layering.py holds the stage table): no file of include/ or
# src/ includes a header of a later stage of the data path; the mesher program includes core
# and mesh only. A second registration runs the check on a tree that breaks the rule three
# times (tests/data/layering) and passes only when all three are reported: the check can fail.
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  set(FLOWFORM_CHECK_LAYERING ${PROJECT_SOURCE_DIR}/scripts/check_layering.py)
  add_test(NAME layering COMMAND ${Python3_EXECUTABLE} ${FLOWFORM_CHECK_LAYERING} ${PROJECT_SOURCE_DIR})
  set_tests_properties(layering PROPERTIES LABELS "unit")
  add_test(NAME layering_detects_violations
           COMMAND ${Python3_EXECUTABLE} ${FLOWFORM_CHECK_LAYERING} ${FLOWFORM_TEST_DATA}/layering)
  # Exit status 1 on the fixture (WILL_FAIL), and each of its three violations in the report.
  set_tests_properties(layering_detects_violations PROPERTIES LABELS "unit" WILL_FAIL TRUE)
  add_test(NAME layering_reports_each_violation
           COMMAND ${Python3_EXECUTABLE} ${FLOWFORM_CHECK_LAYERING} ${FLOWFORM_TEST_DATA}/layering)
  set_tests_properties(layering_reports_each_violation PROPERTIES LABELS "unit"
    PASS_REGULAR_EXPRESSION "include/flowform/mesh/Bad.hpp:3: includes flowform/solvers/[^\n]*later stage[^\n]*\nsrc/mesher/main.cpp:2: includes flowform/solvers/[^\n]*\nsrc/shiny/New.cpp: folder 'shiny' is not in the stage table[^\n]*\n3 layering violation")
endif()
