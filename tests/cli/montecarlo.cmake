# dynpos montecarlo (analysis/montecarlo.hpp): ranges, shards and merging checked at the option.
dynpos_cli_test(montecarlo_bad_seeds
  COMMAND bash ${EXPECT_EXIT} 2 "'1..x' is not a seed range"
          ${DYNPOS_EXE} montecarlo turning-circle --seeds 1..x)
dynpos_cli_test(montecarlo_empty_range
  COMMAND bash ${EXPECT_EXIT} 2 "the range 5..4 is empty"
          ${DYNPOS_EXE} montecarlo turning-circle --seeds 5..4)
dynpos_cli_test(montecarlo_shard_outside
  COMMAND bash ${EXPECT_EXIT} 2 "shard 3/2 does not exist"
          ${DYNPOS_EXE} montecarlo turning-circle --shard 3/2)
dynpos_cli_test(montecarlo_merge_not_a_result
  COMMAND bash ${EXPECT_EXIT} 2 "not a Monte Carlo result"
          ${DYNPOS_EXE} montecarlo merge ${PROJECT_SOURCE_DIR}/CMakePresets.json)
# One seed of the turning circle: the lever arms' table against truth.
dynpos_cli_test(montecarlo_turning_circle
  COMMAND ${DYNPOS_EXE} montecarlo turning-circle --seeds 7 --jobs 1
  PASS "gnss1.x_m +1 +[-0-9.]+ +0 ")
# Shards as separate processes (examples/scaling/montecarlo-shards.sh, what a job array does),
# merged: the same document as one run of the whole range, byte for byte.
dynpos_cli_test(montecarlo_shards_merge_to_one_run
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/montecarlo_shards.sh ${DYNPOS_EXE}
          ${CLI_OUT}/montecarlo ${PROJECT_SOURCE_DIR}/examples/scaling/montecarlo-shards.sh
  PASS "IDENTICAL")
# A layout vessel, the run cut short of its later setpoints (they are dropped, as simulate does).
dynpos_cli_test(montecarlo_layout_short_run
  COMMAND ${DYNPOS_EXE} montecarlo pure-dp --vessel ${PROJECT_SOURCE_DIR}/data/vessels/osv-80m.toml
          --seeds 1 --duration 400 --jobs 1
  PASS "position_std_north_m +1 +[0-9.]+")
