# cmake -DBIN_DIR=... -DSOURCE_DIR=... -DTARGETS=a;b -P replay.cmake: runs each
# fuzz-replay-<target> over its seed corpus and regression inputs; fails if any fails.
set(failed "")
foreach(target IN LISTS TARGETS)
    execute_process(COMMAND ${BIN_DIR}/fuzz-replay-${target}
                            ${SOURCE_DIR}/tests/fuzz-corpus/${target}
                            ${SOURCE_DIR}/tests/fuzz-regressions/${target}
                    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message("${out}")
    if(NOT status EQUAL 0)
        message("${err}")
        list(APPEND failed ${target})
    endif()
endforeach()
if(failed)
    message(FATAL_ERROR "fuzz targets that failed on a stored input: ${failed}")
endif()
