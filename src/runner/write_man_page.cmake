# Writes the runner's man page: `RUNNER --help-man` (made from its option table, option_docs.h)
# into OUT. Run by the build (CMakeLists.txt) with -DRUNNER=... -DOUT=....
execute_process(COMMAND ${RUNNER} --help-man OUTPUT_FILE ${OUT}.tmp RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    file(REMOVE ${OUT}.tmp)
    message(FATAL_ERROR "${RUNNER} --help-man failed: ${status}")
endif()
file(RENAME ${OUT}.tmp ${OUT})
