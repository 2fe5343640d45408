# Loop caps and the run's wall-clock budget (docs/theory.md §5): runs that cannot converge end
# promptly with exit 3, the results written and summary.json "message" (and stderr) saying why and
# what to try; never a hang. Each case takes seconds.
#
# flowform_budget_test(NAME CASE case.xml [SET P=V ...] [STATUS n] [NP n] [MODE --not-converged|--flagged]
#                      [CONTAINS text ...] [MESSAGE text ...] [WRITTEN file ...])
#   Runs flowform on CASE (a path relative to tests/regression/bad_input, as for
#   flowform_exit_test in BadInput.cmake, which defines FLOWFORM_BAD_INPUT_DIR and check_exit.py)
#   with --quiet and checks the exit status (default 3), stderr (CONTAINS), summary.json's
#   "message" (MESSAGE) and the files written (WRITTEN). MODE --not-converged (default) also
#   checks "converged": false; --flagged only the exit status in summary.json. NP n > 1 runs it
#   under mpiexec on n ranks.

if(NOT Python3_Interpreter_FOUND OR NOT COMMAND flowform_exit_test)
  return()
endif()

function(flowform_budget_test name)
  cmake_parse_arguments(ARG "" "CASE;STATUS;MODE;NP" "SET;CONTAINS;MESSAGE;WRITTEN" ${ARGN})
  if(NOT DEFINED ARG_STATUS)
    set(ARG_STATUS 3)
  endif()
  if(NOT DEFINED ARG_MODE)
    set(ARG_MODE --not-converged)
  endif()
  set(check ${ARG_MODE} --timeout 120)
  foreach(text ${ARG_MESSAGE})
    list(APPEND check "--message-contains=${text}")
  endforeach()
  foreach(file ${ARG_WRITTEN})
    list(APPEND check "--written=${file}")
  endforeach()
  set(np)
  if(ARG_NP)
    set(np NP ${ARG_NP})
  endif()
  flowform_exit_test(${name} CASE ${ARG_CASE} STATUS ${ARG_STATUS} ${np} SET ${ARG_SET} CONTAINS ${ARG_CONTAINS}
                     CHECK ${check} LABELS budgets)
endfunction()

set(FLOWFORM_BUDGET_EXTRUSION ../../../xml/extrusion.xml)

# --- the wall-clock budget: a limit spent before the first continuation stage --------------------
# 1 ms is spent by the time the mesh is made (gmsh), so the first check stops the run: exit 3,
# the last state written, the message naming the parameter and the loop.
flowform_budget_test(budget_time_limit_channel CASE channel_small.xml
  SET "Solver/Time Limit=1e-3"
  CONTAINS "flowform: not converged: wall-clock budget of 0.001 s (Solver/Time Limit) spent in"
  MESSAGE "wall-clock budget of 0.001 s (Solver/Time Limit) spent in the continuation in n and e0, after 0"
  WRITTEN summary.json solution.xdmf)
# On 2 ranks: rank 0's clock decides, so both ranks leave the same loop at the same point.
if(MPIEXEC_EXECUTABLE)
  flowform_budget_test(budget_time_limit_channel_np2 CASE channel_small.xml NP 2
    SET "Solver/Time Limit=1e-3"
    CONTAINS "flowform: not converged: wall-clock budget of 0.001 s (Solver/Time Limit) spent in"
    MESSAGE "wall-clock budget of 0.001 s (Solver/Time Limit) spent in the continuation in n and e0, after 0"
    WRITTEN summary.json solution.xdmf)
endif()
# The same in the adaptive loop (extrusion, coarse): the message names the loops it ran in.
flowform_budget_test(budget_time_limit_adaptive CASE ${FLOWFORM_BUDGET_EXTRUSION}
  SET "Mesh/Geo Parameters/h=0.2" "Solver/Time Limit=1e-3"
  CONTAINS "(Solver/Time Limit) spent in"
  MESSAGE "wall-clock budget of 0.001 s (Solver/Time Limit) spent in" "within the adaptivity loop, after 0 cycle(s)"
  WRITTEN summary.json solution.xdmf)
# A negative limit is bad input (exit 2, nothing written).
flowform_exit_test(bad_input_time_limit_negative CASE channel_small.xml SET "Solver/Time Limit=-1"
  CONTAINS "Time Limit")

# --- the hang of the hostile battery: walls with Normal Penalty Factor 1e-300 ---------------------
# The walls carry no load and ram_force is zero to round-off; its relative error (noise / noise)
# never met, the adaptive loop refined to Maximum Dofs for Maximum Cycles (hours). Now cycle 0
# says so and stops: exit 3, in seconds.
flowform_budget_test(budget_zero_response_penalty_1e-300 CASE ${FLOWFORM_BUDGET_EXTRUSION} MODE --flagged
  SET "Boundary Conditions/container/Normal Penalty Factor=1e-300"
      "Boundary Conditions/die_face/Normal Penalty Factor=1e-300"
      "Boundary Conditions/die_land/Normal Penalty Factor=1e-300"
  CONTAINS "flowform: not converged:" "is zero to the solver's resolution"
  MESSAGE "cycle 0: the target response ram_force" "Normal Penalty Factor" "Adaptivity/Enabled=false"
  WRITTEN summary.json)

# --- ordinary physics that does not converge says what and what to try ----------------------------
# n = 1 on the coarse extrusion with the paper's status loop: seven die-land nodes cycle between
# active and free (the default, complementarity, converges there: test contact_cycling_cases).
flowform_budget_test(contact_cycling_message CASE ${FLOWFORM_BUDGET_EXTRUSION}
  SET "Adaptivity/Enabled=false" "Mesh/Geo Parameters/h=0.2" "Material/Rate Exponent=1"
      "Contact/Status Update=Certain Iterate"
  CONTAINS "flowform: not converged: the contact status does not settle"
  MESSAGE "7 node(s) cycle between active and free" "on wall 'die_land' at x 0.214..0.643, y = 0.5"
          "Boundary Conditions/die_land/Released Nodes=Never" "Contact/Max Changes Per Node"
  WRITTEN summary.json)
# The cases where the paper's loop cycles converge with the default, complementarity (no node has
# a status to cycle; docs/contact.md): n = 1, a larger cutoff, no yield stress on the coarse mesh.
foreach(variant "Material/Rate Exponent=1" "Material/Strain Rate Cutoff=1e-2" "Material/Yield Stress=0")
  string(REGEX REPLACE "[^A-Za-z0-9]+" "_" tag "${variant}")
  flowform_exit_test(contact_cycling_converges_${tag} CASE ${FLOWFORM_BUDGET_EXTRUSION} STATUS 0 CONVERGED
    SET "Adaptivity/Enabled=false" "Mesh/Geo Parameters/h=0.2" "${variant}")
endforeach()

# --- a user .msh with an adaptive case: exit 2, the reason and the ways forward ------------------
flowform_exit_test(bad_input_adaptive_msh CASE ${FLOWFORM_BUDGET_EXTRUSION}
  SET "Mesh/File=../tests/data/unit_square_tri.msh"
  CONTAINS "is not a .geo, and the case asks for adaptivity" "remeshing the .geo"
           "Adaptivity/Enabled=false" "Mesh/Uniform Refinements")
