# Bad-input regression tests: flowform must exit with status 2, say on stderr which file,
# parameter or group is wrong, and write nothing (docs/theory.md §5). Plus one good tiny case that
# must exit 0 with summary.json saying converged.
#
# Most cases are the small channel (bad_input/channel_small.xml, N = 2) broken by --set;
# separate XML files only where --set cannot express the fault (malformed XML, an
# ill-typed entry in the file, a group the mesh lacks, a mesh with an inverted cell).
# Each test runs check_exit.py, which removes the output directory first and then checks
# status, stderr and that the directory was not created.

find_package(Python3 COMPONENTS Interpreter)
if(NOT Python3_Interpreter_FOUND)
  message(STATUS "flowform: python3 not found, bad-input regression tests not registered")
  return()
endif()

set(FLOWFORM_BAD_INPUT_DIR ${CMAKE_CURRENT_SOURCE_DIR}/regression/bad_input)
set(FLOWFORM_BAD_INPUT_OUT ${CMAKE_CURRENT_BINARY_DIR}/regression/bad_input)
set(FLOWFORM_CHECK_EXIT ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_exit.py)

# flowform_exit_test(NAME CASE case.xml [SET P=V ...] [ARGS ...] [CONTAINS text ...]
#                    [STATUS n] [NP n] [LABELS l ...]
#                    [CONVERGED | OUTDIR_IS_A_FILE | SUMMARY_IS_A_DIRECTORY | CHECK option ...])
#   Runs flowform on bad_input/CASE with -o <build>/regression/bad_input/NAME, the --set
#   overrides and extra arguments, and checks exit status n (default 2), that stderr
#   contains each CONTAINS text, and that nothing was written (or, with CONVERGED, that
#   summary.json says converged; with OUTDIR_IS_A_FILE / SUMMARY_IS_A_DIRECTORY, that the
#   file or directory put in the way first is left as it was; with CHECK, check_exit.py's
#   options as given instead). NP n > 1 runs it under mpiexec on n ranks. LABELS: besides
#   `regression`.
function(flowform_exit_test name)
  cmake_parse_arguments(ARG "CONVERGED;OUTDIR_IS_A_FILE;SUMMARY_IS_A_DIRECTORY" "CASE;STATUS;NP" "SET;ARGS;CONTAINS;CHECK;LABELS" ${ARGN})
  if(NOT DEFINED ARG_STATUS)
    set(ARG_STATUS 2)
  endif()
  set(outdir ${FLOWFORM_BAD_INPUT_OUT}/${name})
  set(check --outdir ${outdir} --status ${ARG_STATUS})
  foreach(text ${ARG_CONTAINS})
    list(APPEND check "--stderr-contains=${text}")
  endforeach()
  if(ARG_CONVERGED)
    list(APPEND check --converged)
  elseif(ARG_OUTDIR_IS_A_FILE)
    list(APPEND check --outdir-is-a-file)
  elseif(ARG_SUMMARY_IS_A_DIRECTORY)
    list(APPEND check --summary-is-a-directory)
  elseif(ARG_CHECK)
    list(APPEND check ${ARG_CHECK})
  else()
    list(APPEND check --no-output)
  endif()
  set(command $<TARGET_FILE:flowform> ${FLOWFORM_BAD_INPUT_DIR}/${ARG_CASE} -o ${outdir} --quiet)
  foreach(assignment ${ARG_SET})
    list(APPEND command --set ${assignment})
  endforeach()
  list(APPEND command ${ARG_ARGS})
  set(labels regression ${ARG_LABELS})
  if(ARG_NP AND ARG_NP GREATER 1)
    set(command ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${ARG_NP} ${command})
  endif()
  add_test(NAME ${name} COMMAND ${Python3_EXECUTABLE} ${FLOWFORM_CHECK_EXIT} ${check} -- ${command})
  set_tests_properties(${name} PROPERTIES LABELS "${labels}" TIMEOUT 300
                       WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  if(ARG_NP AND ARG_NP GREATER 1)
    set_tests_properties(${name} PROPERTIES ENVIRONMENT "${FLOWFORM_MPI_ENV}" PROCESSORS ${ARG_NP})
  endif()
endfunction()

# --- the good case: the base of every bad one runs -------------------------------------------
flowform_exit_test(regression_good_channel_small CASE channel_small.xml STATUS 0 CONVERGED)

# --- the output directory: checked before any work (a solve is not lost to a bad -o) ------------
flowform_exit_test(bad_input_outdir_is_a_file CASE channel_small.xml OUTDIR_IS_A_FILE
  CONTAINS "exists and is not a directory")
# A result the run could not put in place (summary.json is a directory) is found before the solve:
# exit 2, the directory left as it was.
flowform_exit_test(bad_input_outdir_summary_is_a_directory CASE channel_small.xml SUMMARY_IS_A_DIRECTORY
  CONTAINS "summary.json" "not a regular file")
flowform_exit_test(bad_input_outdir_summary_is_a_directory_np2 CASE channel_small.xml SUMMARY_IS_A_DIRECTORY NP 2
  CONTAINS "summary.json" "not a regular file")
# A directory that cannot be created (under /proc, where access() says yes to root), an empty name.
flowform_exit_test(bad_input_outdir_under_proc CASE channel_small.xml ARGS -o /proc/flowform_out
  CONTAINS "/proc/flowform_out" "cannot be created")
flowform_exit_test(bad_input_outdir_empty CASE channel_small.xml ARGS -o @EMPTY@
  CONTAINS "-o needs a directory name")

# --- the case file -----------------------------------------------------------------------------
flowform_exit_test(bad_input_malformed_xml CASE malformed.xml
  CONTAINS "malformed.xml" "not a valid XML parameter list")
flowform_exit_test(bad_input_missing_case_file CASE nosuch_case.xml
  CONTAINS "nosuch_case.xml" "does not exist")

# --- parameter names and types ---------------------------------------------------------------
flowform_exit_test(bad_input_unknown_parameter CASE channel_small.xml
  SET "Material/Rate Exponnent=5"
  CONTAINS "Rate Exponnent")
flowform_exit_test(bad_input_ill_typed_parameter CASE ill_typed.xml
  CONTAINS "Rate Exponent" "double")
# A parameter with a range validator: Teuchos 13.2's EnhancedNumberValidator converts a
# string entry with std::stod, whose exception says only "stod".
flowform_exit_test(bad_input_ill_typed_validated_parameter CASE ill_typed_validated.xml
  CONTAINS "Yield Stress" "half")
flowform_exit_test(bad_input_set_type_error CASE channel_small.xml
  SET "Material/Rate Exponent=abc"
  CONTAINS "Material/Rate Exponent" "abc" "double")
flowform_exit_test(bad_input_set_no_value CASE channel_small.xml
  SET "Material/Rate Exponent"
  CONTAINS "Material/Rate Exponent" "Path/To/Param=value")
flowform_exit_test(bad_input_unknown_element_type CASE channel_small.xml
  SET "Mesh/Element Type=Hexagon"
  CONTAINS "Element Type" "Hexagon")
flowform_exit_test(bad_input_unknown_ordering CASE channel_small.xml
  SET "Solver/Linear Solver/Ordering=LU"
  CONTAINS "Linear Solver" "Ordering" "LU" "Nested Dissection" "AMD")
# Either ordering solves the good case.
flowform_exit_test(regression_good_channel_small_amd CASE channel_small.xml STATUS 0 CONVERGED
  SET "Solver/Linear Solver/Ordering=AMD")

# --- material constants: n > 0, σ0 >= 0, γ > 0, e0 > 0 ------------------------------------------
flowform_exit_test(bad_input_rate_exponent_zero CASE channel_small.xml
  SET "Material/Rate Exponent=0"
  CONTAINS "Rate Exponent")
flowform_exit_test(bad_input_rate_exponent_negative CASE channel_small.xml
  SET "Material/Rate Exponent=-1"
  CONTAINS "Rate Exponent")
flowform_exit_test(bad_input_yield_stress_negative CASE channel_small.xml
  SET "Material/Yield Stress=-0.5"
  CONTAINS "Yield Stress")
flowform_exit_test(bad_input_rate_constant_zero CASE channel_small.xml
  SET "Material/Rate Constant=0"
  CONTAINS "Rate Constant")
flowform_exit_test(bad_input_rate_constant_negative CASE channel_small.xml
  SET "Material/Rate Constant=-2"
  CONTAINS "Rate Constant")
flowform_exit_test(bad_input_cutoff_zero CASE channel_small.xml
  SET "Material/Strain Rate Cutoff=0"
  CONTAINS "Strain Rate Cutoff")
flowform_exit_test(bad_input_cutoff_negative CASE channel_small.xml
  SET "Material/Strain Rate Cutoff=-1e-3"
  CONTAINS "Strain Rate Cutoff")

# --- sensitivity (docs/theory.md §4) ---------------------------------------------------------
flowform_exit_test(bad_input_sensitivity_unknown_parameter CASE channel_small.xml
  SET "Sensitivity/Parameters={Yield Stres}"
  CONTAINS "Yield Stres" "'Yield Stress'" "'Rate Exponent'")
flowform_exit_test(bad_input_sensitivity_friction_without_walls CASE channel_small.xml
  SET "Sensitivity/Parameters={Friction Coefficient}"
  CONTAINS "Friction Coefficient" "no contact wall")
flowform_exit_test(bad_input_sensitivity_unknown_entry CASE channel_small.xml
  SET "Sensitivity/Finite Diference Step=1e-4"
  CONTAINS "Finite Diference Step")
flowform_exit_test(bad_input_sensitivity_zero_step CASE channel_small.xml
  SET "Sensitivity/Parameters={Yield Stress}" "Sensitivity/Finite Difference Step=0"
  CONTAINS "Finite Difference Step")

# --- mesh and groups ---------------------------------------------------------------------------
flowform_exit_test(bad_input_missing_mesh_file CASE channel_small.xml
  SET "Mesh/File=nosuch_mesh.geo"
  CONTAINS "nosuch_mesh.geo")
flowform_exit_test(bad_input_missing_group CASE missing_group.xml
  CONTAINS "nosuch")
flowform_exit_test(bad_input_inverted_cell CASE inverted.xml
  CONTAINS "inverted" "unit_square_flipped.msh")

# --- contact walls (bad_input/contact_small.xml: the top of the unit square is a Coulomb wall) ----
flowform_exit_test(regression_good_contact_small CASE contact_small.xml STATUS 0 CONVERGED)
flowform_exit_test(bad_input_contact_wall_missing_group CASE contact_small.xml
  SET "Boundary Conditions/nosuch_wall/Type=Contact Wall"
  CONTAINS "nosuch_wall" "no boundary group")
flowform_exit_test(bad_input_friction_coefficient_negative CASE contact_small.xml
  SET "Boundary Conditions/top/Friction Coefficient=-0.1"
  CONTAINS "Friction Coefficient" "top")
flowform_exit_test(bad_input_penalty_viscosity_negative CASE contact_small.xml
  SET "Boundary Conditions/top/Penalty Viscosity=-1.0"
  CONTAINS "Penalty Viscosity" "top")
flowform_exit_test(bad_input_material_sensitivity_with_tresca CASE contact_small.xml
  SET "Boundary Conditions/top/Friction Law=Tresca" "Boundary Conditions/top/Shear Factor=0.5"
      "Sensitivity/Parameters={Yield Stress}"
  CONTAINS "Yield Stress" "Tresca" "top")
flowform_exit_test(bad_input_contact_wall_zero_length_segment CASE contact_small.xml
  SET "Mesh/File=../../data/unit_square_zero_segment.msh"
  CONTAINS "top" "zero-length segment" "unit_square_zero_segment.msh")
# A moving tool (Tool Motion, docs/contact.md "Moving tools"): it must move tangentially to its own
# surface; it cannot turn, nor move radially, in an axisymmetric case; the motion is one of three.
flowform_exit_test(bad_input_tool_motion_not_tangent CASE contact_small.xml
  SET "Boundary Conditions/top/Tool Motion=Translation" "Boundary Conditions/top/Tool Velocity X=1.0"
      "Boundary Conditions/top/Tool Velocity Y=0.1"
  CONTAINS "Boundary Conditions/top/Tool Motion" "tangentially" "Tangency Tolerance")
flowform_exit_test(bad_input_tool_rotation_off_centre CASE contact_small.xml
  SET "Boundary Conditions/top/Tool Motion=Rotation" "Boundary Conditions/top/Angular Velocity=1.0"
      "Boundary Conditions/top/Rotation Centre X=0.5" "Boundary Conditions/top/Rotation Centre Y=-10.0"
  CONTAINS "Boundary Conditions/top/Tool Motion" "tangentially")
flowform_exit_test(bad_input_tool_rotation_straight_wall_no_centre CASE contact_small.xml
  SET "Boundary Conditions/top/Tool Motion=Rotation" "Boundary Conditions/top/Angular Velocity=1.0"
  CONTAINS "Boundary Conditions/top/Tool Motion = Rotation" "straight line" "Rotation Centre X and Y")
flowform_exit_test(bad_input_tool_rotation_axisymmetric CASE contact_small.xml
  SET "Problem/Geometry=Axisymmetric" "Boundary Conditions/top/Tool Motion=Rotation"
      "Boundary Conditions/top/Angular Velocity=1.0"
  CONTAINS "Boundary Conditions/top/Tool Motion = Rotation" "axisymmetric" "Translation along the axis")
flowform_exit_test(bad_input_tool_translation_radial_axisymmetric CASE contact_small.xml
  SET "Problem/Geometry=Axisymmetric" "Boundary Conditions/top/Tool Motion=Translation"
      "Boundary Conditions/top/Tool Velocity X=1.0"
  CONTAINS "Boundary Conditions/top/Tool Motion = Translation" "Tool Velocity X")
flowform_exit_test(bad_input_tool_motion_unknown CASE contact_small.xml
  SET "Boundary Conditions/top/Tool Motion=Sliding"
  CONTAINS "Boundary Conditions/top" "Tool Motion" "Sliding")
# The good one: a tool translating along the wall converges.
flowform_exit_test(regression_good_tool_translation CASE contact_small.xml STATUS 0 CONVERGED
  SET "Boundary Conditions/top/Tool Motion=Translation" "Boundary Conditions/top/Tool Velocity X=0.5")

# --- command line ------------------------------------------------------------------------------
flowform_exit_test(bad_input_unknown_option CASE channel_small.xml
  ARGS --no-such-option
  CONTAINS "--no-such-option")

# --- on 2 ranks: every rank stops with status 2, none waits for another ------------------------
if(MPIEXEC_EXECUTABLE)
  flowform_exit_test(bad_input_missing_group_np2 CASE missing_group.xml NP 2
    CONTAINS "nosuch")
  flowform_exit_test(bad_input_inverted_cell_np2 CASE inverted.xml NP 2
    CONTAINS "inverted")
endif()

# Entries the friction law does not read are said on stderr (a warning, exit 0: a law switched by
# --set keeps the old law's entries), and so is a law's parameter left at its default 0.
flowform_exit_test(warn_friction_entries_the_law_ignores CASE contact_small.xml STATUS 0 CONVERGED
  SET "Boundary Conditions/top/Friction Law=Tresca"
  CONTAINS "warning" "top" "does not use 'Friction Coefficient'" "uses 'Shear Factor', which is not given")

# --- meshing: gmsh runs in the mesher process (docs/theory.md §5) ----------------------------------
# A size gmsh aborts on inside its OpenMP regions (h < 0 where the .geo declares no range): the
# mesher dies, the run says so with gmsh's message, exit 2 — on 1 and 2 ranks.
flowform_exit_test(bad_input_gmsh_aborts CASE channel_small.xml
  SET "Mesh/File=../../data/square_unranged.geo" "Mesh/Geo Parameters/h=-0.1"
  CONTAINS "square_unranged.geo" "gmsh failed" "Wrong mesh element size")
flowform_exit_test(bad_input_gmsh_aborts_np2 CASE channel_small.xml NP 2
  SET "Mesh/File=../../data/square_unranged.geo" "Mesh/Geo Parameters/h=-0.1"
  CONTAINS "square_unranged.geo" "gmsh failed" "Wrong mesh element size")
# A curve loop that crosses itself.
flowform_exit_test(bad_input_geo_self_crossing CASE channel_small.xml
  SET "Mesh/File=../../data/self_crossing.geo" "Mesh/Element Type=Triangle"
  CONTAINS "self_crossing.geo")
# A .geo's declared ranges are input validation (extrusion.geo: h in [1e-4, 1]; cutting.geo:
# alpha in [-30, 45], which the cutting scene took to a 300 s run of 311 604 dofs).
flowform_exit_test(bad_input_geo_parameter_below_declared_min CASE ../../../xml/extrusion.xml
  SET "Mesh/Geo Parameters/h=0"
  CONTAINS "Mesh/Geo Parameters/h" "[0.0001, 1]")
flowform_exit_test(bad_input_geo_parameter_above_declared_max CASE ../../../xml/cutting.xml
  SET "Mesh/Geo Parameters/alpha=89"
  CONTAINS "Mesh/Geo Parameters/alpha" "[-30, 45]")
flowform_exit_test(bad_input_geo_parameter_not_a_choice CASE ../../../xml/extrusion.xml
  SET "Mesh/Geo Parameters/quads=0.5"
  CONTAINS "Mesh/Geo Parameters/quads" "{0, 1}")
# A .geo loop that does not end: Mesh/Time Limit stops the mesher.
flowform_exit_test(bad_input_geo_endless_loop CASE channel_small.xml
  SET "Mesh/File=../../data/endless_loop.geo" "Mesh/Time Limit=2"
  CONTAINS "endless_loop.geo" "did not finish within 2 s")
# Meshes too large to make: estimated before meshing (from the 1-D mesh) or refining (exactly).
flowform_exit_test(bad_input_mesh_too_many_refinements CASE channel_small.xml
  SET "Mesh/Uniform Refinements=14"
  CONTAINS "Maximum Cells" "refining it 14 times")
flowform_exit_test(bad_input_mesh_size_too_small CASE ../../../xml/die_swell.xml
  SET "Mesh/Size Factor=0.001"
  CONTAINS "die_swell.geo" "estimated from its 1-D mesh" "Maximum Cells")
flowform_exit_test(bad_input_mesh_size_factor_out_of_range CASE channel_small.xml
  SET "Mesh/Size Factor=1e-300"
  CONTAINS "Size Factor")
# Two nodes at one point (a slit).
flowform_exit_test(bad_input_mesh_coincident_nodes CASE contact_small.xml
  SET "Mesh/File=../../data/unit_square_slit.msh"
  CONTAINS "unit_square_slit.msh" "nodes 9 and 11")
# What a .geo may do (README): shell commands, file writes, files outside its folder are refused.
flowform_exit_test(bad_input_geo_system_call CASE channel_small.xml
  SET "Mesh/File=../../data/system_call.geo"
  CONTAINS "system_call.geo" "line 2" "SystemCall")
flowform_exit_test(bad_input_geo_printf_to_file CASE channel_small.xml
  SET "Mesh/File=../../data/printf_to_file.geo"
  CONTAINS "printf_to_file.geo" "line 4" "redirection")
flowform_exit_test(bad_input_geo_include_outside CASE channel_small.xml
  SET "Mesh/File=../../data/include_outside.geo"
  CONTAINS "include_outside.geo" "outside the folder")

# --- on several ranks, an input error found on one rank only (a boundary-condition conflict at a
# corner node, checked by the rank that owns it) ends every rank with exit 2 -----------------------
if(MPIEXEC_EXECUTABLE)
  foreach(np 2 3)
    flowform_exit_test(bad_input_conflict_on_one_rank_np${np} CASE channel_small.xml NP ${np}
      SET "Boundary Conditions/inlet/Velocity Y=1.0"
      CONTAINS "conflict")
  endforeach()
endif()

# --- two runs writing the same output directory at once leave one run's whole result set ---------
add_test(NAME output_concurrent_runs_same_outdir
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/regression/concurrent_output.py  # h5py: Debian's python
                 $<TARGET_FILE:flowform> ${FLOWFORM_BAD_INPUT_DIR}/channel_small.xml
                 ${FLOWFORM_BAD_INPUT_OUT}/concurrent)
set_tests_properties(output_concurrent_runs_same_outdir PROPERTIES LABELS regression TIMEOUT 300
                     PROCESSORS 2)
