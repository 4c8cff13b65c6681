# Inputs that used to end in a wrong result, a hang, an abort or a raw control sequence: each
# refused with exit 2 naming the file or the option, or run within bounds.

# --wind-tolerance 1e-300 never ended (the bisection cannot narrow below one ulp).
dynpos_cli_test(capability_wind_tolerance_out_of_range
  COMMAND bash ${EXPECT_EXIT} 2
          "\\(--wind-tolerance\\): the wind tolerance must be from 1e-06 to 10 m/s, got 1e-300"
          timeout 60 ${DYNPOS_EXE} capability --wind-tolerance 1e-300)
# --direction-step inf printed "L1(99,99,99,99)" with exit 0: no direction at all.
dynpos_cli_test(capability_direction_step_infinite
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--direction-step\\): inf deg does not divide 360"
          ${DYNPOS_EXE} capability --direction-step inf)
dynpos_cli_test(capability_direction_step_above_360
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--direction-step\\): 720 deg does not divide 360"
          ${DYNPOS_EXE} capability --direction-step 720)
# An output in a missing folder, or in a folder that takes no file, is refused before the run
# (they exited 1 after it).
dynpos_cli_test(thrust_map_apply_out_missing_folder
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--out\\): folder '.*/no/such' does not exist"
          ${DYNPOS_EXE} identify thrust-map ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv --apply
          --col rpm.port=cmd --unit rpm.port=rpm --out ${CLI_OUT}/no/such/x.csv)
dynpos_cli_test(json_in_proc_refused
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--json\\): cannot write in folder '/proc': it takes no new files"
          ${DYNPOS_EXE} hybrid first-order --json /proc/x.json)
# leverarm mru --w1 -1 named the observer's field w1_per_s (exit 1).
dynpos_cli_test(leverarm_mru_bad_w1
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--w1\\): -1 is not a gain"
          ${DYNPOS_EXE} leverarm mru ${CMAKE_CURRENT_SOURCE_DIR}/short_steps.csv --w1 -1)
# An empty vessel file was the built-in vessel, unsaid.
dynpos_cli_test(simulate_empty_vessel
  COMMAND bash ${EXPECT_EXIT} 2 "empty_vessel.toml: the vessel file has no key"
          ${DYNPOS_EXE} simulate surge-steps-forward --duration 5 --out ${CLI_OUT}/empty_vessel
          --vessel ${CMAKE_CURRENT_SOURCE_DIR}/empty_vessel.toml)
# Names, labels, keys and file names reach the terminal as text.
dynpos_cli_test(terminal_text
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/terminal_text.sh ${DYNPOS_EXE} ${CLI_OUT}/terminal_text
  PASS "^ok")
# Where no thread could start (`ulimit -v`) every subcommand aborted (exit 134). Not with the
# sanitizers, whose shadow memory needs far more address space.
if(NOT DYNPOS_SANITIZE)
  dynpos_cli_test(threads_limited
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/threads_limited.sh ${DYNPOS_EXE}
            ${CLI_OUT}/threads_limited
    PASS "^ok")
endif()
# Outputs on a read-only file system (a read-only tmpfs in a mount namespace; skipped where
# none can be made).
dynpos_cli_test(readonly_fs
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/readonly_fs.sh ${DYNPOS_EXE} PASS "^ok")
set_tests_properties(cli_readonly_fs PROPERTIES SKIP_RETURN_CODE 77)
# A control rate off the simulator's grid exited 1 naming neither the file nor the key.
dynpos_cli_test(simulate_bad_control_rate
  COMMAND bash ${EXPECT_EXIT} 2
          "bad_control_rate.toml \\(joystick.control_rate_hz\\): 3 Hz: the control period 1/3 s is not a whole number"
          ${DYNPOS_EXE} simulate surge-steps-forward --duration 5 --out ${CLI_OUT}/control_rate
          --vessel ${CMAKE_CURRENT_SOURCE_DIR}/bad_control_rate.toml)
# A statistic that overflowed was printed "—", the mark for a figure not logged.
dynpos_cli_test(station_keeping_overflow_is_not_missing
  COMMAND ${DYNPOS_EXE} identify station-keeping ${CMAKE_CURRENT_SOURCE_DIR}/huge_positions.csv
          --col north=north --col east=east
  PASS "position std north \\[m\\] +inf\n" FAIL "position std north \\[m\\] +—")
