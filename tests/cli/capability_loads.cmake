# dynpos capability --loads: the factor of each load of a table on a vessel's thruster layout.
set(LOADS_DATA ${CMAKE_CURRENT_SOURCE_DIR}/data)
dynpos_cli_test(capability_loads_worst
  COMMAND ${DYNPOS_EXE} capability --loads ${LOADS_DATA}/loads_osv.csv
          --vessel ${LOADS_DATA}/osv_layout.toml
  PASS "5 units from \\[\\[thruster\\]\\].*\n.*\n +0\\.0 +2\\.31[0-9]+ +group:bus B +main_port")
dynpos_cli_test(capability_loads_json
  COMMAND ${DYNPOS_EXE} capability --loads ${LOADS_DATA}/loads_osv.csv
          --vessel ${LOADS_DATA}/osv_layout.toml --failure none --json -
  PASS "\"analysis\": \"capability-loads\".*\"load_factor\": 5\\.333")
dynpos_cli_test(capability_loads_model_units
  COMMAND ${DYNPOS_EXE} capability --loads ${LOADS_DATA}/loads_osv.csv --failure tunnel
  PASS "3 units from the vessel model: port, stb, tunnel")
dynpos_cli_test(capability_loads_unknown_unit
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--failure\\): no unit or group 'bow3'.*group:bus B"
          ${DYNPOS_EXE} capability --loads ${LOADS_DATA}/loads_osv.csv
          --vessel ${LOADS_DATA}/osv_layout.toml --failure bow3)
dynpos_cli_test(capability_loads_not_with_level
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--loads\\): --level is not an option"
          ${DYNPOS_EXE} capability --loads ${LOADS_DATA}/loads_osv.csv --level 2)
dynpos_cli_test(capability_loads_bad_cell
  COMMAND bash ${EXPECT_EXIT} 2 "bad_loads\\.csv:3:1 \\(direction_deg\\): 'north' is not a finite number"
          ${DYNPOS_EXE} capability --loads ${CMAKE_CURRENT_SOURCE_DIR}/bad_loads.csv)
