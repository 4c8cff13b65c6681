# dynpos simulate writes gnssK.nmea (NMEA 0183 GGA, RMC, VTG, HDT) beside log.csv.
dynpos_cli_test(simulate_nmea
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/nmea_simulate.sh ${DYNPOS_EXE} ${CLI_OUT}/nmea
  PASS "^ok")
