# Inputs without end: every reader stops at a stated bound (docs/reliability.md, "Limits").
dynpos_cli_test(bounded_inputs
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/bounded_inputs.sh ${DYNPOS_EXE} ${CLI_OUT}/bounded_inputs
          ${PROJECT_SOURCE_DIR} $<IF:$<BOOL:${DYNPOS_SANITIZE}>,no-memory-limit,memory-limit>
  PASS "^ok")
