# dynpos identify failure-test: thruster trips, excursion, recovery and thrust redistribution.
dynpos_cli_test(identify_failure_test
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/failure_test.sh ${DYNPOS_EXE} ${CLI_OUT}/failure_test
  PASS "^ok")
dynpos_cli_test(identify_failure_test_no_feedback
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*no unit feedback channel \\(thrust.NAME or rpm.NAME\\)"
          ${DYNPOS_EXE} identify failure-test ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response)
dynpos_cli_test(identify_failure_test_no_position
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*no position in the log"
          ${DYNPOS_EXE} identify failure-test ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col thrust.port=response --unit thrust.port=kN)
dynpos_cli_test(identify_failure_test_arm_without_heading
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*the lever arm \\(--arm\\) needs the heading"
          ${DYNPOS_EXE} identify failure-test ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col thrust.port=response --unit thrust.port=kN --col north=response
          --col east=response --arm 1,0)
dynpos_cli_test(identify_failure_test_bad_hold
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--hold\\): -1 s must be ≥ 0"
          ${DYNPOS_EXE} identify failure-test ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col thrust.port=response --unit thrust.port=kN --hold -1)
