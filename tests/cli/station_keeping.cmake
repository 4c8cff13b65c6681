# dynpos identify station-keeping: pure-DP statistics (thesis tables 3.11-3.22).
dynpos_cli_test(identify_station_keeping
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/station_keeping.sh ${DYNPOS_EXE}
          ${CLI_OUT}/station_keeping
  PASS "^ok")
dynpos_cli_test(identify_station_keeping_no_position
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*no position in the log.*north="
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv)
dynpos_cli_test(identify_station_keeping_window_outside
  COMMAND bash ${EXPECT_EXIT} 2 "the window 100 … 400 s starts after the log's last row at 70 s"
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --from 100 --to 400)
dynpos_cli_test(identify_station_keeping_no_setpoints
  COMMAND bash ${EXPECT_EXIT} 2 "--per-setpoint needs the DP setpoints"
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --per-setpoint)
# The same bad window, the same message in every windowed analysis (LogSource::load).
dynpos_cli_test(identify_window_errors_four_corner_station_keeping
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/window_errors.sh ${DYNPOS_EXE}
          ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
  PASS "^ok")
dynpos_cli_test(identify_station_keeping_partly_outside
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--from/--to\\): the window 50 … 100 s is not inside the log \\(0 … 70 s\\)"
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --from 50 --to 100)
