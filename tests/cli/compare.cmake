# dynpos compare: two results of the same analysis side by side (thesis ch. 3, work item 5).
set(COMPARE_DATA ${CMAKE_CURRENT_SOURCE_DIR}/data/compare)
dynpos_cli_test(compare
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/compare.sh ${DYNPOS_EXE} ${CLI_OUT}/compare
  PASS "^ok")
dynpos_cli_test(compare_help COMMAND ${DYNPOS_EXE} compare --help
  PASS "--json.*--format.*--labels")
dynpos_cli_test(compare_different_kinds
  COMMAND bash ${EXPECT_EXIT} 2 "cannot compare a 'step' result .*steps_aug.json.* with a 'four-corner' result .*legs_after.json"
          ${DYNPOS_EXE} compare ${COMPARE_DATA}/steps_aug.json ${COMPARE_DATA}/legs_after.json)
dynpos_cli_test(compare_invalid_json
  COMMAND bash ${EXPECT_EXIT} 2 "broken.json:3:31.*invalid JSON"
          ${DYNPOS_EXE} compare ${COMPARE_DATA}/steps_aug.json ${COMPARE_DATA}/broken.json)
dynpos_cli_test(compare_nothing_in_common
  COMMAND bash ${EXPECT_EXIT} 2 "no numeric figure in common"
          ${DYNPOS_EXE} compare ${COMPARE_DATA}/generic_a.json ${COMPARE_DATA}/generic_b.json)
dynpos_cli_test(compare_bad_labels
  COMMAND bash ${EXPECT_EXIT} 2 "--labels.*not two labels"
          ${DYNPOS_EXE} compare ${COMPARE_DATA}/steps_aug.json ${COMPARE_DATA}/steps_nov.json
          --labels "only one")
dynpos_cli_test(compare_bad_format
  COMMAND bash ${EXPECT_EXIT} 2 "unknown format 'html'"
          ${DYNPOS_EXE} compare ${COMPARE_DATA}/steps_aug.json ${COMPARE_DATA}/steps_nov.json
          --format html)
dynpos_cli_test(compare_missing_file
  COMMAND bash ${EXPECT_EXIT} 2 "no_such.json"
          ${DYNPOS_EXE} compare ${COMPARE_DATA}/steps_aug.json ${COMPARE_DATA}/no_such.json)
dynpos_cli_test(compare_json_folder_missing
  COMMAND bash ${EXPECT_EXIT} 2 "does not exist"
          ${DYNPOS_EXE} compare ${COMPARE_DATA}/steps_aug.json ${COMPARE_DATA}/steps_nov.json
          --json ${CLI_OUT}/compare/no/such/dir/c.json)
