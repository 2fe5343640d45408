# Channel verification against the exact solution (tests/verification/ChannelExact.hpp).
add_executable(ChannelConvergence verification/ChannelConvergence.cpp)
target_link_libraries(ChannelConvergence PRIVATE flowform_lib)
target_compile_options(ChannelConvergence PRIVATE ${FLOWFORM_WARNINGS})
target_compile_definitions(ChannelConvergence PRIVATE FLOWFORM_SOURCE_DIR="${FLOWFORM_SOURCE_DIR}")
add_test(NAME channel_convergence COMMAND ChannelConvergence --check --max-n 32)
set_tests_properties(channel_convergence PROPERTIES LABELS "regression")
add_test(NAME channel_convergence_fine COMMAND ChannelConvergence --check --max-n 64)
set_tests_properties(channel_convergence_fine PROPERTIES LABELS "slow")
add_test(NAME pipe_axisym_convergence COMMAND ChannelConvergence --check --max-n 16 --pipe)
set_tests_properties(pipe_axisym_convergence PROPERTIES LABELS "regression")
# Scale robustness: γ from 10⁻¹ to 10³ (velocities scale with γ), converged and accurate.
add_test(NAME channel_rate_constant COMMAND ChannelConvergence --rate-constant)
set_tests_properties(channel_rate_constant PROPERTIES LABELS "regression")
