# Silent wrong values: a parameter that runs (exit 0) with a value other than the one written.
# Each class must be bad input instead: exit 2, the parameter named on stderr, nothing written
# (io/CaseFile.hpp for the case file, core/NumberRange.hpp for the ranges). Uses
# flowform_exit_test and the small channel of BadInput.cmake (included before this file);
# the XML fixtures are bad_input/*.xml, each channel_small.xml with one fault.

if(NOT COMMAND flowform_exit_test)
  return()  # no python3: BadInput.cmake said so
endif()

# --- a parameter or sublist given twice in the case file ----------------------------------------
flowform_exit_test(bad_input_duplicate_parameter CASE duplicate_parameter.xml
  CONTAINS "Material/Yield Stress is given twice" "duplicate_parameter.xml" "lines 8 and 9")
flowform_exit_test(bad_input_duplicate_sublist CASE duplicate_sublist.xml
  CONTAINS "sublist Solver is given twice" "duplicate_sublist.xml")

# --- ill-typed values in the file (Teuchos reads "abc" as 0 and "5,5" as 5) ----------------------
flowform_exit_test(bad_input_ill_typed_comma CASE ill_typed_comma.xml
  CONTAINS "Material/Rate Exponent" "'5,5'" "not a double" "ill_typed_comma.xml")
flowform_exit_test(bad_input_ill_typed_abc CASE ill_typed_abc.xml
  CONTAINS "Material/Strain Rate Cutoff" "'abc'" "not a double")

# --- non-finite numbers: in the file, and by --set -----------------------------------------------
flowform_exit_test(bad_input_non_finite_inf CASE non_finite_inf.xml
  CONTAINS "Material/Strain Rate Cutoff" "'inf'" "not a finite number")
flowform_exit_test(bad_input_non_finite_nan_traction CASE non_finite_nan.xml
  CONTAINS "Boundary Conditions/inlet/Traction X" "'nan'" "not a finite number")
flowform_exit_test(bad_input_non_finite_overflow_geo_parameter CASE non_finite_overflow.xml
  CONTAINS "Mesh/Geo Parameters/N" "'1e400'" "not a finite number")
flowform_exit_test(bad_input_set_non_finite_inf CASE channel_small.xml
  SET "Material/Strain Rate Cutoff=inf"
  CONTAINS "Material/Strain Rate Cutoff" "'inf'" "finite")
flowform_exit_test(bad_input_set_non_finite_nan_traction CASE channel_small.xml
  SET "Boundary Conditions/inlet/Traction X=nan"
  CONTAINS "Boundary Conditions/inlet/Traction X" "'nan'" "finite")
flowform_exit_test(bad_input_set_non_finite_geo_parameter CASE channel_small.xml
  SET "Mesh/Geo Parameters/N=1e400"
  CONTAINS "Mesh/Geo Parameters/N" "'1e400'" "finite")

# --- a UTF-8 byte-order mark: a valid document, read and run -------------------------------------
flowform_exit_test(regression_good_byte_order_mark CASE byte_order_mark.xml STATUS 0 CONVERGED)

# --- out of range: every number has the range its meaning allows (core/NumberRange.hpp) ---------
flowform_exit_test(bad_input_dead_zone_reference_speed_negative CASE channel_small.xml
  SET "Responses/dz/Type=Dead Zone" "Responses/dz/Reference Speed=-1.0"
  CONTAINS "Responses/dz" "Reference Speed" "> 0")
flowform_exit_test(bad_input_dead_zone_fraction_zero CASE channel_small.xml
  SET "Responses/dz/Type=Dead Zone" "Responses/dz/Fraction=0"
  CONTAINS "Responses/dz" "Fraction = 0" "in (0, 1")  # no square brackets: they would join CMake list items
flowform_exit_test(bad_input_start_exponent_zero CASE channel_small.xml
  SET "Solver/Continuation/Start Exponent=0"
  CONTAINS "Solver/Continuation/Start Exponent" "> 0")
flowform_exit_test(bad_input_start_cutoff_negative CASE channel_small.xml
  SET "Solver/Continuation/Start Cutoff=-0.1"
  CONTAINS "Solver/Continuation/Start Cutoff" "> 0")
flowform_exit_test(bad_input_update_tolerance_zero CASE channel_small.xml
  SET "Solver/Update Tolerance=0"
  CONTAINS "Solver/Update Tolerance" "> 0")
flowform_exit_test(bad_input_relative_tolerance_one CASE channel_small.xml
  SET "Solver/Relative Residual Tolerance=1"
  CONTAINS "Solver/Relative Residual Tolerance = 1" "0, 1)")
flowform_exit_test(bad_input_normal_penalty_zero CASE contact_small.xml
  SET "Boundary Conditions/top/Normal Penalty Factor=0"
  CONTAINS "Boundary Conditions/top" "Normal Penalty Factor" "> 0")
flowform_exit_test(bad_input_norton_exponent_zero CASE contact_small.xml
  SET "Boundary Conditions/top/Friction Law=Norton" "Boundary Conditions/top/Norton Exponent=0"
  CONTAINS "Boundary Conditions/top" "Norton Exponent" "> 0")

# --- a shape parameter the case does not give in Mesh/Geo Parameters ------------------------------
flowform_exit_test(bad_input_sensitivity_unknown_geo_parameter CASE channel_small.xml
  SET "Sensitivity/Parameters={Geo Parameter:Q}"
  CONTAINS "Geo Parameter:Q" "Mesh/Geo Parameters" "allowed")
