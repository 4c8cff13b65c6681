# dynpos estimate: the DP observer over a logged run; the bias as a time series.
dynpos_cli_test(estimate
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/estimate.sh ${DYNPOS_EXE} ${CLI_OUT}/estimate
  PASS "^ok")
dynpos_cli_test(estimate_no_thrust
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv \\(thrust.port\\).*no thrust of unit 'port'.*--col thrust.port=COLUMN"
          ${DYNPOS_EXE} estimate ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --col heading=cmd --unit heading=rad)
dynpos_cli_test(estimate_no_heading
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv \\(heading\\).*the observer needs the heading"
          ${DYNPOS_EXE} estimate ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response)
dynpos_cli_test(estimate_raw_observer
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--observer\\): the observer must be passive or ekf, got 'raw'"
          ${DYNPOS_EXE} estimate ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv --observer raw)
dynpos_cli_test(estimate_bad_tp
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--tp\\): the wave peak period must be from 2 to 20 s, got 30"
          ${DYNPOS_EXE} estimate ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv --tp 30)
dynpos_cli_test(estimate_unknown_mru
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--mru\\): the vessel .* has no MRU 'mru9'"
          ${DYNPOS_EXE} estimate ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --col heading=cmd --unit heading=rad
          --mru mru9)
dynpos_cli_test(estimate_mru_without_channels
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv \\(mru1.ax\\).*no mru1.ax with a valid sample in the log for the bridge.*--mru none"
          ${DYNPOS_EXE} estimate ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --col heading=cmd --unit heading=rad
          --mru mru1)
