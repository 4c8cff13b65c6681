# dynpos identify four-corner: legs, durations, accumulated thrust and energy (table 3.6).
dynpos_cli_test(identify_four_corner
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/four_corner.sh ${DYNPOS_EXE} ${CLI_OUT}/four_corner
  PASS "^ok")
dynpos_cli_test(identify_four_corner_no_heading
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*no heading in the log"
          ${DYNPOS_EXE} identify four-corner ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response)
dynpos_cli_test(identify_four_corner_no_leg
  COMMAND bash ${EXPECT_EXIT} 2 "no leg found"
          ${DYNPOS_EXE} identify four-corner ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=flat --col east=flat --col heading=flat --unit north=m --unit east=m --unit heading=rad)
dynpos_cli_test(identify_four_corner_bad_segment
  COMMAND bash ${EXPECT_EXIT} 2 "unknown segmentation 'box'"
          ${DYNPOS_EXE} identify four-corner ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --col heading=flat --unit heading=rad --segment box)
dynpos_cli_test(identify_four_corner_window_outside
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv \\(--from/--to\\): the window from 5000 s on starts after the log's last row at 70 s"
          ${DYNPOS_EXE} identify four-corner ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col north=response --col east=response --col heading=flat --unit heading=rad --from 5000)
