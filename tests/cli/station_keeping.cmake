# dynpos identify station-keeping: pure-DP statistics (thesis tables 3.11-3.22).
dynpos_cli_test(identify_station_keeping
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/station_keeping.sh ${DYNPOS_EXE}
          ${CLI_OUT}/station_keeping
  PASS "^ok")
dynpos_cli_test(identify_station_keeping_no_position
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*no position in the log.*north="
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv)
dynpos_cli_test(identify_station_keeping_window_outside
  COMMAND bash ${EXPECT_EXIT} 2 "not inside the log"
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --from 100 --to 400)
dynpos_cli_test(identify_station_keeping_no_setpoints
  COMMAND bash ${EXPECT_EXIT} 2 "--per-setpoint needs the DP setpoints"
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --per-setpoint)
