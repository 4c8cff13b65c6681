# Options several subcommands share (apps/dynpos/output_options.cpp).
# --seed takes 0 … 2^64−1 in decimal on every subcommand; "-1" used to wrap to 2^64−1.
dynpos_cli_test(seed_negative_refused
  COMMAND bash ${EXPECT_EXIT} 2 "--seed: '-1' is not a seed: give a whole number from 0 to 18446744073709551615"
          ${DYNPOS_EXE} hybrid first-order --seed -1)
dynpos_cli_test(seed_overflow_refused
  COMMAND bash ${EXPECT_EXIT} 2 "'18446744073709551616' is not a seed"
          ${DYNPOS_EXE} simulate surge-steps-forward --seed 18446744073709551616 --out ${CLI_OUT}/seed)
dynpos_cli_test(seed_largest_taken
  COMMAND ${DYNPOS_EXE} hybrid dp --sampled --end-time 12 --seed 18446744073709551615 --json -
  PASS "\"seed\": 18446744073709551615")
# --json "" used to exit 0 having written nothing.
dynpos_cli_test(json_empty_name_refused
  COMMAND bash ${EXPECT_EXIT} 2 "--json: an empty name writes nothing"
          bash -c "exec \"$1\" hybrid first-order --json ''" _ ${DYNPOS_EXE})
# --out - used to make a folder named "-": standard output cannot hold a folder of files.
dynpos_cli_test(out_dash_refused
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--out\\): '-' \\(standard output\\) cannot hold a folder of files"
          ${DYNPOS_EXE} simulate surge-steps-forward --duration 10 --out -)
dynpos_cli_test(work_dir_dash_refused
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--work-dir\\): '-' \\(standard output\\) cannot hold a folder"
          ${DYNPOS_EXE} montecarlo surge-steps-forward --seeds 1..2 --work-dir -)
# A role given twice with --col used to keep the last one silently.
dynpos_cli_test(col_role_twice_refused
  COMMAND bash ${EXPECT_EXIT} 2 "role 'input' is given twice: 'input=a' and 'input=b'"
          ${DYNPOS_EXE} identify step ${PROJECT_SOURCE_DIR}/tests/cli/short_steps.csv
          --col input=a --col input=b --col output=y)
# A --duration out of the scenario's range used to be blamed on the scenario file's duration_s.
dynpos_cli_test(duration_out_of_range_names_the_option
  COMMAND bash ${EXPECT_EXIT} 2 "surge-steps-forward.toml \\(--duration\\): value 1e\\+300 is out of range"
          ${DYNPOS_EXE} simulate surge-steps-forward --duration 1e300 --out ${CLI_OUT}/duration)
# Finding M6: a pipe was read twice (header, then rows) and its second read started mid-stream.
# "-" reads standard input, and a pipe or FIFO as LOG is read once, into a temporary copy.
dynpos_cli_test(log_from_standard_input
  COMMAND bash -c "cat \"$2\" | \"$1\" identify step - --col input=cmd --col output=response"
          _ ${DYNPOS_EXE} ${PROJECT_SOURCE_DIR}/tests/cli/short_steps.csv
  PASS "input: - \\(csv, time stamps: seconds, 701 records\\)")
dynpos_cli_test(log_from_a_pipe_names_it
  COMMAND bash ${EXPECT_EXIT} 2 "^dynpos: error: /dev/stdin:1 \\(output\\): column 'x' for role 'output' is not in the header"
          bash -c "cat \"$2\" | \"$1\" identify step /dev/stdin --col input=cmd --col output=x"
          _ ${DYNPOS_EXE} ${PROJECT_SOURCE_DIR}/tests/cli/short_steps.csv)
dynpos_cli_test(nmea_capture_from_standard_input
  COMMAND bash -c "\"$1\" identify station-keeping - --json - < \"$2\""
          _ ${DYNPOS_EXE} ${PROJECT_SOURCE_DIR}/tests/data/nmea/station.nmea
  PASS "\"format\": \"nmea\"")
# Finding M1: a run streams its files to disk a block at a time (scenario/run_files.hpp); one
# whose files cannot fit the disk (10⁶ s at 100 Hz: about 154 GB) is refused before it starts,
# and nothing is written.
dynpos_cli_test(simulate_too_large_for_disk_refused
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--out\\): the files would take about 154.0 GB. .* is free on the disk of"
          ${DYNPOS_EXE} simulate pure-dp --duration 1000000 --log-rate 100 --out ${CLI_OUT}/huge)
# Out of memory is exit 2 with the command and what to do, not "std::bad_alloc" (exit 1): 20
# million rows on standard input need about 480 MB of columns, more than the 400 MB allowed.
# Memory is capped with ulimit, which AddressSanitizer's reservations cannot run under: the
# sanitizer pass leaves this test out (label rlimit).
dynpos_cli_test(out_of_memory_is_an_input_error
  COMMAND bash ${EXPECT_EXIT} 2 "^dynpos: error: out of memory running 'identify step - --col input=cmd --col output=x'. give a shorter log or run"
          bash -c "(echo 'time [s],cmd,x' && seq -f '%.0f,1,2' 1 20000000) | (ulimit -v 400000 && exec \"$1\" identify step - --col input=cmd --col output=x)"
          _ ${DYNPOS_EXE})
set_tests_properties(cli_out_of_memory_is_an_input_error PROPERTIES LABELS rlimit)
dynpos_cli_test(signal_removes_temporary_files
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/signal_cleanup.sh ${DYNPOS_EXE}
          ${PROJECT_SOURCE_DIR}/tests/cli/short_steps.csv ${CLI_OUT}/signal
  PASS "^ok")
# Finding M4: a run's files appear together or not at all. A file named "devices" where the run
# puts a folder stops the run before any file is placed: the old log.csv stays, no stage left.
dynpos_cli_test(simulate_outputs_appear_together_or_not_at_all
  COMMAND bash -c "rm -rf \"$2\" && mkdir -p \"$2\" && echo old > \"$2/log.csv\" && echo x > \"$2/devices\" && \"$1\" simulate surge-steps-forward --duration 10 --out \"$2\"; code=$?; [ $code = 2 ] && [ \"$(cat \"$2/log.csv\")\" = old ] && [ -z \"$(ls -A \"$2\" | grep -v -x -e log.csv -e devices)\" ] && echo together-or-nothing"
          _ ${DYNPOS_EXE} ${CLI_OUT}/together
  PASS "together-or-nothing")
# An output folder that cannot be made was "filesystem error: …" with exit 1.
dynpos_cli_test(output_folder_that_cannot_be_made
  COMMAND bash ${EXPECT_EXIT} 2 "^dynpos: error: '.*/plain-file/plots': Not a directory. check the path"
          bash -c "mkdir -p \"$2\" && touch \"$2/plain-file\" && exec \"$1\" hybrid first-order --out \"$2/plain-file/plots\""
          _ ${DYNPOS_EXE} ${CLI_OUT}/mkdir)
# A library's field names ("CaseTiming: end_time") stay out of the message; the option is named.
dynpos_cli_test(hybrid_end_time_names_the_option
  COMMAND bash ${EXPECT_EXIT} 2 "^dynpos: error: \\(--end-time\\): end_time must be finite and > 0"
          ${DYNPOS_EXE} hybrid first-order --end-time -1)
