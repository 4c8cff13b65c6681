# Time stamps of a log (docs/log-format.md, "Time stamps"), through the shared log options.
dynpos_cli_test(time_stamps_iso8601
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/time_stamps.sh ${DYNPOS_EXE} ${CLI_OUT}/time_stamps
  PASS "^ok")
dynpos_cli_test(time_stamps_unknown_format
  COMMAND bash ${EXPECT_EXIT} 2 "time-format.*unknown time format 'iso'.*iso8601"
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --time-format iso)
dynpos_cli_test(time_stamps_bad_date
  COMMAND bash ${EXPECT_EXIT} 2 "date.*'2024-02-30' is not a date"
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --date 2024-02-30)
dynpos_cli_test(time_stamps_forced_format_mismatch
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv:2:1 \\(time \\[s\\]\\): '0.0' is not a time of day"
          ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --time-format time-of-day)
