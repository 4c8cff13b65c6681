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

# The DNV levels on a layout: its units, unit and group failures, the worst case naming them.
dynpos_cli_test(capability_layout_rose
  COMMAND ${DYNPOS_EXE} capability --vessel ${LOADS_DATA}/azimuth_layout.toml --direction-step 90
  PASS "vessel Gunnerus hull, azimuth test layout: DP capability-L1\\(10,5,8,0\\).*\n0 +10 +31\\.[0-9] +az_port\\+az_stb +8 +23\\.9 +az_stb +az_port")
dynpos_cli_test(capability_layout_group
  COMMAND ${DYNPOS_EXE} capability --vessel ${LOADS_DATA}/azimuth_layout.toml --direction-step 90
          --failure group:stb --json -
  PASS "\"layout\": \"\\[\\[thruster\\]\\]\".*\"failure\": \"group:stb\"")
dynpos_cli_test(capability_layout_unknown_case
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--failure\\): no unit or group 'port' in the layout of .*azimuth_layout\\.toml. one of az_port, az_stb, tunnel, group:port, group:stb"
          ${DYNPOS_EXE} capability --vessel ${LOADS_DATA}/azimuth_layout.toml --failure port)
# The simulator runs a layout's own units: level 3 and simulate take it; manual rudder steps,
# which name the model's two rudders, are refused.
dynpos_cli_test(capability_layout_level_3
  COMMAND ${DYNPOS_EXE} capability --vessel ${LOADS_DATA}/azimuth_layout.toml --level 3
          --direction-step 180 --duration 60 --settle 30 --json -
  PASS "\"layout\": \"\\[\\[thruster\\]\\]\".*\"level\": 3")
dynpos_cli_test(simulate_layout
  COMMAND ${DYNPOS_EXE} simulate pure-dp --vessel ${LOADS_DATA}/azimuth_layout.toml --duration 30
          --out ${CMAKE_CURRENT_BINARY_DIR}/simulate_layout
  PASS "simulated 'pure-dp' \\(30 s, seed 1\\): 301 rows")
dynpos_cli_test(simulate_layout_rudder_steps_refused
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--vessel\\): the scenario 'yaw-steps' steps the model's two rudders by hand, and .*azimuth_layout\\.toml has a \\[\\[thruster\\]\\] layout of 3 units"
          ${DYNPOS_EXE} simulate yaw-steps --vessel ${LOADS_DATA}/azimuth_layout.toml
          --out ${CMAKE_CURRENT_BINARY_DIR}/simulate_layout_refused)
# --apply with a layout: each unit's map is its drive's (ρK_T D⁴ ahead and astern).
dynpos_cli_test(thrust_map_apply_layout
  COMMAND ${DYNPOS_EXE} identify thrust-map ${LOADS_DATA}/layout_rpm.csv --apply
          --out ${CMAKE_CURRENT_BINARY_DIR}/thrust_map_apply_layout.csv
          --vessel ${LOADS_DATA}/azimuth_layout.toml --col rpm.az_port=az_port --col rpm.tunnel=tunnel
  PASS "thrust of 2 thruster\\(s\\) from .*azimuth_layout\\.toml")
dynpos_cli_test(thrust_map_apply_layout_unknown_unit
  COMMAND bash ${EXPECT_EXIT} 2 "\\(rpm\\.port\\): no thrust map for thruster 'port' in the vessel file. the vessel file has az_port, az_stb, tunnel"
          ${DYNPOS_EXE} identify thrust-map ${LOADS_DATA}/layout_rpm.csv --apply
          --out ${CMAKE_CURRENT_BINARY_DIR}/thrust_map_apply_layout_unknown.csv
          --vessel ${LOADS_DATA}/azimuth_layout.toml --col rpm.port=az_port)
# Level 2 on a layout keeps the units' ratings, and says so in the table and the JSON.
dynpos_cli_test(capability_layout_level_2_says_no_losses
  COMMAND ${DYNPOS_EXE} capability --vessel ${LOADS_DATA}/azimuth_layout.toml --level 2
          --direction-step 90
  PASS "\nno thrust losses: a \\[\\[thruster\\]\\] layout's units keep their ratings at level 2")
dynpos_cli_test(capability_layout_level_2_json
  COMMAND ${DYNPOS_EXE} capability --vessel ${LOADS_DATA}/azimuth_layout.toml --level 2
          --direction-step 90 --json -
  PASS "\"thrust_losses\": false")
# Level 3 with the failure as it happens: per direction the excursion after the tunnel trips
# (beam on it is lost: the footprint is left), and the options that do not go with it refused.
dynpos_cli_test(capability_transient
  COMMAND ${DYNPOS_EXE} capability --level 3 --transient --failure tunnel --direction-step 90
          --rows 3 --settle 60 --after 60 --json -
  PASS "\"analysis\": \"capability-transient\".*\"failure\": \"tunnel\".*\"holds\": false")
dynpos_cli_test(capability_transient_option_without_it
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--rows\\): --rows is an option of --transient.*add --level 3 --transient --failure NAME"
          ${DYNPOS_EXE} capability --rows 3)
dynpos_cli_test(capability_transient_refuses_the_wind_search
  COMMAND bash ${EXPECT_EXIT} 2 "\\(--wind-tolerance\\): --wind-tolerance is not an option of --transient"
          ${DYNPOS_EXE} capability --level 3 --transient --failure tunnel --wind-tolerance 1)
