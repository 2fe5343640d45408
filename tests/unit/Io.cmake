# Output writers: XDMF/HDF5, boundary CSV, JSON summary helpers.
flowform_unit_test(IoTest unit/IoTest.cpp)
