# dynpos identify vessel and compare-trial: the hull of a vessel file from trial logs.
dynpos_cli_test(identify_vessel
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/vessel_id.sh ${DYNPOS_EXE} ${CLI_OUT}/vessel_id
  PASS "^ok")
dynpos_cli_test(identify_vessel_no_heading
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*heading.*the log has no heading"
          ${DYNPOS_EXE} identify vessel ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --out ${CLI_OUT}/no_heading.toml)
dynpos_cli_test(identify_vessel_bad_holdout
  COMMAND bash ${EXPECT_EXIT} 2 "--holdout.*'x.csv' is not one of the logs"
          ${DYNPOS_EXE} identify vessel ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --out ${CLI_OUT}/holdout.toml --holdout x.csv)
dynpos_cli_test(compare_trial_no_thrust
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*thrust.port"
          ${DYNPOS_EXE} compare-trial ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col heading=flat --unit heading=rad)
