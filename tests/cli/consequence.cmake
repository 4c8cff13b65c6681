# dynpos consequence: the worst single failure's margin against the estimated load.
dynpos_cli_test(consequence
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/consequence.sh ${DYNPOS_EXE} ${CLI_OUT}/consequence
  PASS "^ok")
dynpos_cli_test(consequence_bad_window
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--window\\): the mean's window must be > 0 s, got 0"
          ${DYNPOS_EXE} consequence ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv --window 0)
