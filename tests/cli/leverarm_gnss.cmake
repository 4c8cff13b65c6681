# dynpos leverarm gnss: GNSS antenna lever arms (thesis 4.2) on the simulated turning circle.
dynpos_cli_test(leverarm_gnss
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/leverarm_gnss.sh ${DYNPOS_EXE} ${CLI_OUT}/leverarm_gnss
          ${PROJECT_SOURCE_DIR}
  PASS "^ok")
