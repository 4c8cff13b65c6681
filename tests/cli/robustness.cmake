# Inputs that used to end in a wrong result, a hang, an abort or a raw control sequence: each
# refused with exit 2 naming the file or the option, or run within bounds.
# Where no thread could start (`ulimit -v`) every subcommand aborted (exit 134). Not with the
# sanitizers, whose shadow memory needs far more address space.
if(NOT DYNPOS_SANITIZE)
  dynpos_cli_test(threads_limited
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/threads_limited.sh ${DYNPOS_EXE}
            ${CLI_OUT}/threads_limited
    PASS "^ok")
endif()
