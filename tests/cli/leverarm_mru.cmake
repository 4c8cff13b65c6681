# dynpos leverarm mru: MRU lever arms (thesis 4.3) on a short simulated turning circle.
dynpos_cli_test(leverarm_mru
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/leverarm_mru.sh ${DYNPOS_EXE} ${CLI_OUT}/leverarm_mru
  PASS "^ok")
dynpos_cli_test(leverarm_mru_bad_accel
  COMMAND bash ${EXPECT_EXIT} 2 "--accel.*unknown acceleration convention 'gravity'"
          ${DYNPOS_EXE} leverarm mru ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv --accel gravity)
dynpos_cli_test(leverarm_mru_no_mru
  COMMAND bash ${EXPECT_EXIT} 2 "no MRU acceleration channels found"
          ${DYNPOS_EXE} leverarm mru ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv)
