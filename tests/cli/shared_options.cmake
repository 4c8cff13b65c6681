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
