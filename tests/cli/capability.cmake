# dynpos capability: DP capability after DNV-ST-0111 (levels 1-3).
dynpos_cli_test(capability
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/capability.sh ${DYNPOS_EXE} ${CLI_OUT}/capability
  PASS "^ok")
dynpos_cli_test(capability_bad_level
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--level\\): unknown level 4"
          ${DYNPOS_EXE} capability --level 4)
dynpos_cli_test(capability_unknown_failure
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--failure\\): unknown actuator 'bow'"
          ${DYNPOS_EXE} capability --failure bow)
dynpos_cli_test(capability_site_needs_level_2
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--site/--hs/--tp/--current\\): a site environment is for level 2"
          ${DYNPOS_EXE} capability --hs 2)
dynpos_cli_test(capability_bad_direction_step
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--direction-step\\): 7 deg does not divide 360"
          ${DYNPOS_EXE} capability --direction-step 7)
