# Outputs, signals and runs together (docs/reliability.md, "Outputs"): an output that is an
# input, outputs checked before anything is written, write failures, a run's files placed
# together under signals, montecarlo's work folder and shards, the demo's disk and summary.
set(CLI_DIR ${CMAKE_CURRENT_SOURCE_DIR})
dynpos_cli_test(output_is_input
  COMMAND bash ${CLI_DIR}/output_is_input.sh ${DYNPOS_EXE} ${CLI_OUT}/output_is_input ${CLI_DIR}
  PASS "^ok")
dynpos_cli_test(outputs_checked_before_run
  COMMAND bash ${CLI_DIR}/outputs_before_run.sh ${DYNPOS_EXE} ${CLI_OUT}/outputs_before_run
  PASS "^ok")
dynpos_cli_test(write_failures
  COMMAND bash ${CLI_DIR}/write_failures.sh ${DYNPOS_EXE} ${CLI_OUT}/write_failures ${CLI_DIR}
  PASS "^ok")
dynpos_cli_test(run_signal_loop
  COMMAND bash ${CLI_DIR}/run_signal_loop.sh ${DYNPOS_EXE} ${CLI_OUT}/run_signal_loop ${CLI_DIR}
  PASS "^ok")
dynpos_cli_test(montecarlo_signal
  COMMAND bash ${CLI_DIR}/montecarlo_signal.sh ${DYNPOS_EXE} ${CLI_OUT}/montecarlo_signal
          ${CLI_DIR}
  PASS "^ok")
dynpos_cli_test(montecarlo_merge_other_runs
  COMMAND bash ${CLI_DIR}/montecarlo_merge_runs.sh ${DYNPOS_EXE} ${CLI_OUT}/montecarlo_merge_runs
          ${CLI_DIR}
  PASS "^ok")
dynpos_cli_test(demo_small_disk
  COMMAND bash ${CLI_DIR}/demo_small_disk.sh ${DYNPOS_EXE} ${CLI_OUT}/demo_small_disk
  PASS "^ok")
set_tests_properties(cli_demo_small_disk PROPERTIES SKIP_RETURN_CODE 77)
dynpos_cli_test(demo_interrupted
  COMMAND bash ${CLI_DIR}/demo_interrupted.sh ${DYNPOS_EXE} ${CLI_OUT}/demo_interrupted ${CLI_DIR}
          ${PROJECT_SOURCE_DIR}
  PASS "^ok")
