# CTest helpers: register a C++ test plug-in, a script test or a whole suite as a CTest test.
# Each test runs robottestingframework-testrunner; its exit status is the test's verdict
# (0 passed; 1 something failed; 2 usage or configuration error).
#
#   robottestingframework_add_test(NAME name PLUGIN target_or_file
#                                  [PARAM "..."] [ENVIRONMENT "..."] [REPETITION n]
#                                  [TIMEOUT seconds] [JUNIT file] [RUNNER_ARGS ...]
#                                  [TEST_ENVIRONMENT VAR=value ...] [WORKING_DIRECTORY dir]
#                                  [LABELS ...] [WILL_FAIL])
#   robottestingframework_add_script_test(NAME name SCRIPT file ...same options...)
#   robottestingframework_add_suite(NAME name SUITE file.xml
#                                   [ENVIRONMENT "..."] [TIMEOUT seconds] [JUNIT file]
#                                   [RUNNER_ARGS ...] [TEST_ENVIRONMENT ...]
#                                   [WORKING_DIRECTORY dir] [LABELS ...] [WILL_FAIL])
#
# PLUGIN is a shared-library target of this project (its file is used) or a file. Relative
# SCRIPT and SUITE files (and PLUGIN files that exist there) are taken from the current source
# folder. PARAM and ENVIRONMENT are the runner's --param and --environment strings (given to
# the test); TEST_ENVIRONMENT sets variables of the runner's process. TIMEOUT is CTest's time
# limit for the whole run (for the runner's own per-test limit pass RUNNER_ARGS --timeout N).
# JUNIT writes a JUnit XML report there (relative: in the current build folder); without it
# (and without --output in RUNNER_ARGS) the runner writes no result file (--no-output).
#
# The runner is the imported target RobotTestingFramework::robottestingframework-testrunner
# when it exists, else the file in RobotTestingFramework_TESTRUNNER.

include_guard(GLOBAL)

# Resolves a file given to the helpers: absolute, or relative to the current source folder
# when it exists there; anything else is passed on unchanged (the runner searches for it).
function(_robottestingframework_resolve_file file out)
    if(IS_ABSOLUTE "${file}" OR "${file}" MATCHES "^\\$<")
        set(${out} "${file}" PARENT_SCOPE)
    elseif(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${file}")
        set(${out} "${CMAKE_CURRENT_SOURCE_DIR}/${file}" PARENT_SCOPE)
    else()
        set(${out} "${file}" PARENT_SCOPE)
    endif()
endfunction()

function(_robottestingframework_runner out)
    if(TARGET RobotTestingFramework::robottestingframework-testrunner)
        set(${out} "$<TARGET_FILE:RobotTestingFramework::robottestingframework-testrunner>"
            PARENT_SCOPE)
    elseif(RobotTestingFramework_TESTRUNNER)
        set(${out} "${RobotTestingFramework_TESTRUNNER}" PARENT_SCOPE)
    else()
        message(FATAL_ERROR "robottestingframework-testrunner is unknown: call "
                            "find_package(RobotTestingFramework) or set "
                            "RobotTestingFramework_TESTRUNNER")
    endif()
endfunction()

# The shared part: `option` is the runner's option (--test, --suite) for `file`; the rest of
# the arguments are the caller's.
function(_robottestingframework_add_runner_test caller file_keyword option)
    set(flags WILL_FAIL)
    set(one NAME ${file_keyword} PARAM ENVIRONMENT REPETITION TIMEOUT JUNIT WORKING_DIRECTORY)
    set(multi RUNNER_ARGS TEST_ENVIRONMENT LABELS)
    cmake_parse_arguments(PARSE_ARGV 3 arg "${flags}" "${one}" "${multi}")
    if(arg_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR "${caller}: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
    endif()
    if(NOT arg_NAME)
        message(FATAL_ERROR "${caller}: NAME is required")
    endif()
    if(NOT arg_${file_keyword})
        message(FATAL_ERROR "${caller}(${arg_NAME}): ${file_keyword} is required")
    endif()

    set(file "${arg_${file_keyword}}")
    if(file_keyword STREQUAL "PLUGIN" AND TARGET "${file}")
        set(file "$<TARGET_FILE:${file}>")
    else()
        _robottestingframework_resolve_file("${file}" file)
    endif()

    _robottestingframework_runner(runner)
    set(command "${runner}" ${option} "${file}")
    if(DEFINED arg_PARAM)
        list(APPEND command --param "${arg_PARAM}")
    endif()
    if(DEFINED arg_ENVIRONMENT)
        list(APPEND command --environment "${arg_ENVIRONMENT}")
    endif()
    if(DEFINED arg_REPETITION)
        list(APPEND command --repetition "${arg_REPETITION}")
    endif()
    if(arg_JUNIT)
        if(NOT IS_ABSOLUTE "${arg_JUNIT}")
            set(arg_JUNIT "${CMAKE_CURRENT_BINARY_DIR}/${arg_JUNIT}")
        endif()
        list(APPEND command --output "${arg_JUNIT}" --output-type junit)
    elseif(NOT "-o" IN_LIST arg_RUNNER_ARGS AND NOT "--output" IN_LIST arg_RUNNER_ARGS)
        # The verdict is the exit status; no result.txt left in the build folder.
        list(APPEND command --no-output)
    endif()
    list(APPEND command ${arg_RUNNER_ARGS})

    if(arg_WORKING_DIRECTORY)
        add_test(NAME "${arg_NAME}" COMMAND ${command} WORKING_DIRECTORY "${arg_WORKING_DIRECTORY}")
    else()
        add_test(NAME "${arg_NAME}" COMMAND ${command})
    endif()
    if(arg_TIMEOUT)
        set_property(TEST "${arg_NAME}" PROPERTY TIMEOUT "${arg_TIMEOUT}")
    endif()
    if(arg_TEST_ENVIRONMENT)
        set_property(TEST "${arg_NAME}" PROPERTY ENVIRONMENT ${arg_TEST_ENVIRONMENT})
    endif()
    if(arg_LABELS)
        set_property(TEST "${arg_NAME}" PROPERTY LABELS ${arg_LABELS})
    endif()
    if(arg_WILL_FAIL)
        set_property(TEST "${arg_NAME}" PROPERTY WILL_FAIL TRUE)
    endif()
endfunction()

# A C++ test plug-in (a target or a shared-library file), run with --test.
function(robottestingframework_add_test)
    _robottestingframework_add_runner_test(robottestingframework_add_test PLUGIN --test ${ARGN})
endfunction()

# A script test case (.py, .lua, .rb, or any executable), run with --test.
function(robottestingframework_add_script_test)
    _robottestingframework_add_runner_test(robottestingframework_add_script_test SCRIPT --test
                                           ${ARGN})
endfunction()

# A suite file, run with --suite.
function(robottestingframework_add_suite)
    _robottestingframework_add_runner_test(robottestingframework_add_suite SUITE --suite ${ARGN})
endfunction()
