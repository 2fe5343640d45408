# The Python package's own tests (python/flowform_tools, and the scenes' theory under
# tests/regression/ such as cutting/shear_plane.py): plain unittest, one ctest test per
# tests/unit/python/test_<module>.py, named python_<module>, label unit, well under a second each.
# Debian's /usr/bin/python3 (numpy and h5py for h5io); PYTHONPATH is set for every test in
# tests/CMakeLists.txt.
file(GLOB FLOWFORM_PYTHON_UNIT_TESTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/unit/python/test_*.py)
foreach(file ${FLOWFORM_PYTHON_UNIT_TESTS})
  get_filename_component(module ${file} NAME_WE)
  string(REGEX REPLACE "^test_" "python_" name ${module})
  add_test(NAME ${name} COMMAND /usr/bin/python3 -m unittest -v ${module})
  set_tests_properties(${name} PROPERTIES LABELS "unit" TIMEOUT 60
                       WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/unit/python)
endforeach()
