# dynpos identify agility: thrust agility (thesis 3.5.1, figures 3.1-3.3).
dynpos_cli_test(identify_agility
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/agility.sh ${DYNPOS_EXE} ${CLI_OUT}/agility
  PASS "^ok")
dynpos_cli_test(identify_agility_no_thruster
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*no thruster channel"
          ${DYNPOS_EXE} identify agility ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv)
dynpos_cli_test(identify_agility_no_command
  COMMAND bash ${EXPECT_EXIT} 2 "short_steps.csv.*no joystick demand in the log and no --window"
          ${DYNPOS_EXE} identify agility ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col thrust.port=response --unit thrust.port=kN)
dynpos_cli_test(identify_agility_constant_command
  COMMAND bash ${EXPECT_EXIT} 2 "constant"
          ${DYNPOS_EXE} identify agility ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col thrust.port=response --unit thrust.port=kN --col command.surge=flat
          --unit command.surge=% --col command.sway=flat --unit command.sway=%)
dynpos_cli_test(identify_agility_bad_window
  COMMAND bash ${EXPECT_EXIT} 2 "--window.*needs 3 to 5 numbers"
          ${DYNPOS_EXE} identify agility ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col thrust.port=response --unit thrust.port=kN --window 10,20)
dynpos_cli_test(identify_agility_window_outside
  COMMAND bash ${EXPECT_EXIT} 2 "not inside the log"
          ${DYNPOS_EXE} identify agility ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv
          --col thrust.port=response --unit thrust.port=kN --window 10,5000,90)
