# Output writers: XDMF/HDF5, boundary CSV, JSON summary helpers.
flowform_unit_test(IoTest unit/IoTest.cpp)
# Reading the case file (duplicates, ill-typed and non-finite values, BOM) and parameter ranges.
flowform_unit_test(IoCaseFileTest unit/CaseFileTest.cpp)
