# dynpos identify thrust-map: back-calculation and application of T = c·n|n| (3.17)-(3.18).
dynpos_cli_test(identify_thrust_map
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/thrust_map.sh ${DYNPOS_EXE} ${CLI_OUT}/thrust_map
  PASS "^ok")
dynpos_cli_test(identify_thrust_map_no_thrust
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*no thruster with both shaft speed and thrust"
          ${DYNPOS_EXE} identify thrust-map ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv)
dynpos_cli_test(identify_thrust_map_apply_needs_out
  COMMAND bash ${EXPECT_EXIT} 2 "--apply needs --out"
          ${DYNPOS_EXE} identify thrust-map ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv --apply)
