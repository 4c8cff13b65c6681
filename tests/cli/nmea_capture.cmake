# Raw NMEA 0183 captures as logs: detected by content, skipped lines counted, --strict, errors.
set(NMEA_DATA ${PROJECT_SOURCE_DIR}/tests/data/nmea)
dynpos_cli_test(nmea_capture_station_keeping
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/nmea_capture.sh ${DYNPOS_EXE} ${NMEA_DATA}/station.nmea
          ${CLI_OUT}/nmea_capture
  PASS "^ok")
dynpos_cli_test(nmea_capture_strict
  COMMAND bash ${EXPECT_EXIT} 2 "station\\.nmea:1: line not usable \\(truncated\\)"
          ${DYNPOS_EXE} identify station-keeping ${NMEA_DATA}/station.nmea --strict)
dynpos_cli_test(nmea_capture_nothing_usable
  COMMAND bash ${EXPECT_EXIT} 2
          "nothing\\.nmea: no usable NMEA sentence.*1 bad checksum, 1 comment, 3 unknown sentence"
          ${DYNPOS_EXE} identify station-keeping ${NMEA_DATA}/nothing.nmea)
dynpos_cli_test(nmea_capture_forced_csv
  COMMAND bash ${EXPECT_EXIT} 2 "station\\.nmea"
          ${DYNPOS_EXE} identify station-keeping ${NMEA_DATA}/station.nmea --format csv)
dynpos_cli_test(nmea_capture_bad_format
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--format\\): unknown log format 'xml'"
          ${DYNPOS_EXE} identify station-keeping ${NMEA_DATA}/station.nmea --format xml)
dynpos_cli_test(nmea_capture_col_refused
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--col\\): role 'heading' is mapped to a column of .*station.nmea, an NMEA capture"
          ${DYNPOS_EXE} identify station-keeping ${NMEA_DATA}/station.nmea --col heading=HDT)
# Two clocks in one capture (tests/data/nmea/two_clocks.nmea): the sentences of the clock that
# steps back are dropped and counted, not sorted in among the others; --strict stops at the first.
dynpos_cli_test(nmea_capture_clock_back
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/nmea_clock_back.sh ${DYNPOS_EXE}
          ${NMEA_DATA}/two_clocks.nmea ${CLI_OUT}/nmea_clock_back
  PASS "^ok")
dynpos_cli_test(nmea_capture_clock_back_strict
  COMMAND bash ${EXPECT_EXIT} 2
          "two_clocks\\.nmea:4: line not usable \\(time back\\): GGA at 09:59:58\\.500 after 10:00:00\\.000"
          ${DYNPOS_EXE} identify station-keeping ${NMEA_DATA}/two_clocks.nmea --strict)
