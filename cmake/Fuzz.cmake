# Fuzz targets. Each parser of untrusted text has a <name>_fuzz.cpp beside it that defines
# LLVMFuzzerTestOneInput; rtf_add_fuzz_target() declares it.
#  - RTF_FUZZ=ON (clang only): everything is compiled with ASan, UBSan and libFuzzer's coverage
#    hooks, and each file becomes the libFuzzer program fuzz-<name> (target `fuzz` builds them
#    all; ./run.sh fuzz runs them).
#  - Otherwise, with the tests: the same file and tests/fuzz/replay_main.cpp become
#    fuzz-replay-<name>, which the fuzz.regressions test runs over tests/fuzz-corpus/<name>/
#    and tests/fuzz-regressions/<name>/.
option(RTF_FUZZ "Build the libFuzzer targets (needs clang; see ./run.sh fuzz)" OFF)

if(RTF_FUZZ)
    if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
        message(FATAL_ERROR
            "RTF_FUZZ=ON needs clang (libFuzzer), not ${CMAKE_CXX_COMPILER_ID}: configure a new "
            "build folder with -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ "
            "(Debian packages clang and libclang-rt-14-dev), or run ./run.sh fuzz")
    endif()
    # Undefined behaviour stops the input like a crash does, so it is a finding too.
    add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                        -fno-omit-frame-pointer)
    add_link_options(-fsanitize=address,undefined)
    add_custom_target(fuzz)
endif()

set_property(GLOBAL PROPERTY RTF_FUZZ_TARGETS "")

# rtf_add_fuzz_target(NAME SOURCE LIBRARY...): SOURCE (beside the code it drives) linked to the
# libraries it needs.
function(rtf_add_fuzz_target name source)
    if(WIN32)
        return()  # fuzzing and its regression replays run on Linux only
    elseif(RTF_FUZZ)
        add_executable(fuzz-${name} ${source})
        target_link_options(fuzz-${name} PRIVATE -fsanitize=fuzzer)
        add_dependencies(fuzz fuzz-${name})
        set(target fuzz-${name})
    elseif(RTF_BUILD_TESTS)
        add_executable(fuzz-replay-${name} ${source} ${PROJECT_SOURCE_DIR}/tests/fuzz/replay_main.cpp)
        set(target fuzz-replay-${name})
    else()
        return()
    endif()
    target_link_libraries(${target} PRIVATE ${ARGN} rtf_warnings)
    set_property(GLOBAL APPEND PROPERTY RTF_FUZZ_TARGETS ${name})
endfunction()
