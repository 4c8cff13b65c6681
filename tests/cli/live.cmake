# dynpos live: the analyses on a stream, the final result the offline one (live.sh), and the
# stream options' errors.
dynpos_cli_test(live
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/live.sh ${DYNPOS_EXE} ${CLI_OUT}/live
  PASS "^ok")
set_tests_properties(cli_live PROPERTIES TIMEOUT 300)
dynpos_cli_test(live_two_streams
  COMMAND bash ${EXPECT_EXIT} 2 "--udp excludes --follow|--follow excludes --udp"
          ${DYNPOS_EXE} live identify step --udp 127.0.0.1:10110 --follow
          ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv --col input=cmd --col output=response)
dynpos_cli_test(live_no_stream
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--udp/--tcp/--follow\\): no stream given"
          ${DYNPOS_EXE} live identify step --col input=cmd --col output=response)
dynpos_cli_test(live_bad_endpoint
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--udp\\): '127.0.0.1' is not HOST:PORT"
          ${DYNPOS_EXE} live identify station-keeping --udp 127.0.0.1)
dynpos_cli_test(live_bad_port
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--tcp\\): 'localhost:99999' is not HOST:PORT"
          ${DYNPOS_EXE} live leverarm gnss --tcp localhost:99999)
dynpos_cli_test(live_unknown_analysis
  COMMAND bash ${EXPECT_EXIT} 2 "thrust-map"
          ${DYNPOS_EXE} live identify thrust-map --follow
          ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv)
dynpos_cli_test(live_json_to_stdout
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--json\\): standard output carries the live JSON lines"
          ${DYNPOS_EXE} live identify step --follow ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col input=cmd --col output=response --json -)
dynpos_cli_test(live_missing_file
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--follow\\): cannot open '.*no_such.csv'"
          ${DYNPOS_EXE} live identify step --follow ${CLI_OUT}/no_such.csv
          --col input=cmd --col output=response)
# A followed file that ends, read whole: --idle-exit gives the final line, equal to the offline
# document (the jq check is in live.sh; here the flag and the exit code).
dynpos_cli_test(live_idle_exit
  COMMAND ${DYNPOS_EXE} live identify step --follow ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col input=cmd --col output=response --idle-exit 0.5
  PASS "\"final\":true}")
# The live help: --json a file only (standard output carries the lines), --strict as it is live.
foreach(analysis "identify;step" "identify;station-keeping" "leverarm;gnss")
  string(REPLACE ";" "_" stem "${analysis}")
  dynpos_cli_test(live_help_${stem} COMMAND ${DYNPOS_EXE} live ${analysis} --help
    PASS "--strict +A bad tag block ends the session.*--json TEXT:FILE +Write the final result"
    FAIL "for stdout|An NMEA line that cannot be used is an error")
endforeach()
