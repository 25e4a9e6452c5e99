# CMake helpers: build a C++ test plug-in, and register a plug-in, a script test or a whole
# suite as a CTest test. Each test runs robottestingframework-testrunner; its exit status is
# the test's verdict (0 passed; 1 something failed; 2 usage or configuration error).
#
#   robottestingframework_add_plugin(name SOURCES file... [HEADERS file...] [OUTPUT_NAME n])
#   robottestingframework_add_test(NAME name PLUGIN target_or_file
#                                  [PARAM "..."] [ENVIRONMENT "..."] [REPETITION n]
#                                  [TIMEOUT seconds] [JUNIT file] [RUNNER_ARGS ...]
#                                  [TEST_ENVIRONMENT VAR=value ...] [WORKING_DIRECTORY dir]
#                                  [LABELS ...] [WILL_FAIL])
#   robottestingframework_add_script_test(NAME name SCRIPT file ...same options...)
#   robottestingframework_add_suite(NAME name SUITE file.xml
#                                   [ENVIRONMENT "..."] [TIMEOUT seconds] [JUNIT file]
#                                   [RUNNER_ARGS ...] [PLUGIN_PATH dir...] [TEST_ENVIRONMENT ...]
#                                   [WORKING_DIRECTORY dir] [LABELS ...] [WILL_FAIL])
#   robottestingframework_discover_tests(SUITE file.xml [NAME_PREFIX prefix]
#                                        [RUNNER_ARGS ...] [PLUGIN_PATH dir...]
#                                        [TEST_ENVIRONMENT ...] [WORKING_DIRECTORY dir]
#                                        [LABELS ...] [TIMEOUT seconds]
#                                        [DISCOVERY_TIMEOUT seconds]
#                                        [WORLD PER_SUITE|PER_TEST])
#   robottestingframework_add_suite(NAME name                              (RTF 2.x's form)
#       [RobotTestingFramework_FIXTURE target_or_file [param words...]]...
#       RobotTestingFramework_TEST target_or_file TYPE type [ARGS param...]...
#       [WORKING_DIRECTORY dir] [CONFIGURATIONS config...] [WEB_REPORTER] [WEB_PORT n]
#       [DETAIL] [VERBOSE] [OUTPUT file] [OUTPUT_TYPE text|junit]
#       [ENVIRONMENT "..."] [TIMEOUT seconds] [RUNNER_ARGS ...] [TEST_ENVIRONMENT ...]
#       [LABELS ...] [WILL_FAIL])
#
# robottestingframework_add_plugin builds a MODULE library without the `lib` prefix, linked to
# RobotTestingFramework::RTF and RTF_dll, as RTF 2.x's function did.
#
# PLUGIN is a shared-library target of this project (its file is used) or a file. Relative
# SCRIPT and SUITE files (and PLUGIN files that exist there) are taken from the current source
# folder. PARAM and ENVIRONMENT are the runner's --param and --environment strings (given to
# the test); TEST_ENVIRONMENT sets variables of the runner's process. TIMEOUT is CTest's time
# limit for the whole run (for the runner's own per-test limit pass RUNNER_ARGS --timeout N).
# JUNIT writes a JUnit XML report there (relative: in the current build folder); without it
# (and without --output in RUNNER_ARGS) the runner writes no result file (--no-output).
#
# RTF 2.x's suite form writes the suite file <build folder>/<name>.xml with file(GENERATE) (so
# targets become their files) and runs it: one <fixture> per RobotTestingFramework_FIXTURE
# (the words after it are its param), one <test> per value of ARGS (one without param when
# there is no ARGS). OUTPUT (relative: in the current build folder) and OUTPUT_TYPE are the
# runner's --output and --output-type; without them no result file is written.
#
# The runner is the imported target RobotTestingFramework::RTF_testrunner when it exists, else
# the file in RobotTestingFramework_TESTRUNNER.
#
# Plug-ins of this project: the suite functions pass the runner --plugin-path for the folders
# given in PLUGIN_PATH (generator expressions allowed, e.g. $<TARGET_FILE_DIR:my_module>),
# then for the output folder of every robottestingframework_add_plugin target of the project
# (wherever it is defined, before or after) and CMAKE_LIBRARY_OUTPUT_DIRECTORY when set. So a
# suite in the source tree naming <test type="dll">MyTest</test> finds the MyTest built here.
#
# robottestingframework_discover_tests registers one CTest test per test of the suite, named
# NAME_PREFIX (default: none) followed by the test's id (as `--list` shows it, e.g.
# "arm/JointLimits"); each runs that one test (--filter). The list is read when ctest starts
# (`--list --output json`, as gtest_discover_tests(... DISCOVERY_MODE PRE_TEST) does), so a
# changed suite file needs no new configure; each test gets the LABELS and its tags as labels.
# A suite that cannot be listed gives one failing test, NAME_PREFIX followed by the suite
# file's name and "/list", whose output is the runner's error. Needs CMake 3.19 at test time.
# The tests of one suite never run at once (a RESOURCE_LOCK of the suite file). WORLD PER_SUITE
# (the default): a suite with fixtures sets them up once for all its tests, in two more tests,
# NAME_PREFIX followed by the suite's name and "/world:up" (a CTest FIXTURES_SETUP: the runner's
# --world-up keeps the world in a process of its own) and "/world:down" (FIXTURES_CLEANUP); its
# tests run in that world (--world); `ctest -R` adds the two to the tests it picks. WORLD
# PER_TEST: each test sets the suite's fixtures up and tears them down itself (what Windows
# always does: no world keeper there). docs/how-to/ctest-worlds.md.

include_guard(GLOBAL)

include("${CMAKE_CURRENT_LIST_DIR}/RobotTestingFrameworkBracket.cmake")

# The script ctest runs to list a suite's tests (beside this file in both trees).
set(_ROBOTTESTINGFRAMEWORK_DISCOVER_SCRIPT
    "${CMAKE_CURRENT_LIST_DIR}/RobotTestingFrameworkDiscoverTests.cmake")

# The plug-in folders of the project, read at generate time (a target property can hold
# generator expressions; a global property could not be read by one).
if(NOT TARGET _robottestingframework_plugin_folders)
    add_library(_robottestingframework_plugin_folders INTERFACE)
endif()

# The runner's --plugin-path options for `folders` (the caller's PLUGIN_PATH), then the
# project's plug-in folders, in `out` (a list; expand with COMMAND_EXPAND_LISTS).
function(_robottestingframework_plugin_path_args folders out)
    set(target _robottestingframework_plugin_folders)
    set(all "")
    foreach(folder IN LISTS folders)
        string(APPEND all "${folder}$<SEMICOLON>")
    endforeach()
    if(CMAKE_LIBRARY_OUTPUT_DIRECTORY)
        string(APPEND all "${CMAKE_LIBRARY_OUTPUT_DIRECTORY}$<SEMICOLON>")
    endif()
    string(APPEND all "$<TARGET_GENEX_EVAL:${target},"
                      "$<TARGET_PROPERTY:${target},INTERFACE_RTF_PLUGIN_FOLDERS>>")
    # Each folder once, in order; no empty one.
    set(all "$<FILTER:$<REMOVE_DUPLICATES:${all}>,EXCLUDE,^$>")
    set(option "--plugin-path$<SEMICOLON>")
    set(${out} "$<$<BOOL:${all}>:${option}$<JOIN:${all},$<SEMICOLON>${option}>>" PARENT_SCOPE)
endfunction()

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
    if(TARGET RobotTestingFramework::RTF_testrunner)
        set(${out} "$<TARGET_FILE:RobotTestingFramework::RTF_testrunner>" PARENT_SCOPE)
    elseif(TARGET RobotTestingFramework::robottestingframework-testrunner)
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
    set(multi RUNNER_ARGS TEST_ENVIRONMENT LABELS PLUGIN_PATH)
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
    if(file_keyword STREQUAL "SUITE")
        _robottestingframework_plugin_path_args("${arg_PLUGIN_PATH}" plugin_path)
        list(APPEND command ${plugin_path})
    elseif(arg_PLUGIN_PATH)
        message(FATAL_ERROR "${caller}(${arg_NAME}): PLUGIN_PATH is for suites")
    endif()

    if(arg_WORKING_DIRECTORY)
        add_test(NAME "${arg_NAME}" COMMAND ${command} WORKING_DIRECTORY "${arg_WORKING_DIRECTORY}"
                 COMMAND_EXPAND_LISTS)
    else()
        add_test(NAME "${arg_NAME}" COMMAND ${command} COMMAND_EXPAND_LISTS)
    endif()
    _robottestingframework_test_properties()
endfunction()

# The CTest properties every helper offers, from the caller's parsed arg_* variables.
macro(_robottestingframework_test_properties)
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
endmacro()

# A C++ test plug-in (a target or a shared-library file), run with --test.
function(robottestingframework_add_test)
    _robottestingframework_add_runner_test(robottestingframework_add_test PLUGIN --test ${ARGN})
endfunction()

# A script test case (.py, .lua, .rb, or any executable), run with --test.
function(robottestingframework_add_script_test)
    _robottestingframework_add_runner_test(robottestingframework_add_script_test SCRIPT --test
                                           ${ARGN})
endfunction()

# A suite: a file run with --suite, or RTF 2.x's form that describes the suite in place.
function(robottestingframework_add_suite)
    if("SUITE" IN_LIST ARGN)
        _robottestingframework_add_runner_test(robottestingframework_add_suite SUITE --suite
                                               ${ARGN})
    else()
        _robottestingframework_add_generated_suite(${ARGN})
    endif()
endfunction()

# A C++ test or fixture plug-in, as RTF 2.x built them: a module without the `lib` prefix.
function(robottestingframework_add_plugin name)
    cmake_parse_arguments(PARSE_ARGV 1 arg "" "OUTPUT_NAME" "SOURCES;HEADERS")
    if(arg_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR "robottestingframework_add_plugin(${name}): unknown arguments: "
                            "${arg_UNPARSED_ARGUMENTS}")
    endif()
    if(NOT arg_SOURCES)
        message(FATAL_ERROR "robottestingframework_add_plugin(${name}): SOURCES is required")
    endif()
    add_library(${name} MODULE ${arg_SOURCES} ${arg_HEADERS})
    set_target_properties(${name} PROPERTIES PREFIX "")
    # Its folder is searched by the suites of this project (--plugin-path).
    set_property(TARGET _robottestingframework_plugin_folders APPEND
                 PROPERTY INTERFACE_RTF_PLUGIN_FOLDERS "$<TARGET_FILE_DIR:${name}>")
    if(arg_OUTPUT_NAME)
        set_target_properties(${name} PROPERTIES OUTPUT_NAME "${arg_OUTPUT_NAME}")
    endif()
    # The plain signature, as RTF 2.x's: its users add libraries with plain calls too.
    target_link_libraries(${name} RobotTestingFramework::RTF RobotTestingFramework::RTF_dll)
endfunction()

function(_robottestingframework_xml_escape text out)
    string(REPLACE "&" "&amp;" text "${text}")
    string(REPLACE "<" "&lt;" text "${text}")
    string(REPLACE ">" "&gt;" text "${text}")
    string(REPLACE "\"" "&quot;" text "${text}")
    set(${out} "${text}" PARENT_SCOPE)
endfunction()

# A target becomes its file (a generator expression); a file is resolved as the helpers do.
function(_robottestingframework_plugin_file plugin out)
    if(TARGET "${plugin}")
        set(${out} "$<TARGET_FILE:${plugin}>" PARENT_SCOPE)
    else()
        _robottestingframework_resolve_file("${plugin}" file)
        _robottestingframework_xml_escape("${file}" file)
        set(${out} "${file}" PARENT_SCOPE)
    endif()
endfunction()

# The suite file's elements for one RobotTestingFramework_FIXTURE (kind FIXTURE: the words
# after it are its param) or RobotTestingFramework_TEST (kind TEST: a TYPE, one <test> per ARGS
# value), in `out`.
function(_robottestingframework_suite_elements where kind name file type words args out)
    set(elements "")
    if(kind STREQUAL "FIXTURE")
        string(JOIN " " param ${words})
        _robottestingframework_xml_escape("${param}" param)
        if(param STREQUAL "")
            set(elements "  <fixture>${file}</fixture>\n")
        else()
            set(elements "  <fixture param=\"${param}\">${file}</fixture>\n")
        endif()
    else()
        if(type STREQUAL "")
            message(FATAL_ERROR "${where}: RobotTestingFramework_TEST ${name} has no TYPE "
                                "(e.g. TYPE dll)")
        endif()
        if(words)
            message(FATAL_ERROR "${where}: RobotTestingFramework_TEST ${name}: unexpected "
                                "${words} (the tests' params go after ARGS)")
        endif()
        _robottestingframework_xml_escape("${type}" type)
        if(NOT args)
            set(elements "  <test type=\"${type}\">${file}</test>\n")
        endif()
        foreach(param IN LISTS args)
            _robottestingframework_xml_escape("${param}" param)
            string(APPEND elements "  <test type=\"${type}\" param=\"${param}\">${file}</test>\n")
        endforeach()
    endif()
    set(${out} "${elements}" PARENT_SCOPE)
endfunction()

# RTF 2.x's form of robottestingframework_add_suite. The fixture and test groups repeat, so
# the arguments are read one by one rather than with cmake_parse_arguments.
function(_robottestingframework_add_generated_suite)
    set(caller robottestingframework_add_suite)
    set(flags WEB_REPORTER DETAIL VERBOSE WILL_FAIL)
    set(one NAME WORKING_DIRECTORY WEB_PORT OUTPUT OUTPUT_TYPE ENVIRONMENT TIMEOUT)
    set(multi CONFIGURATIONS RUNNER_ARGS TEST_ENVIRONMENT LABELS)
    set(groups RobotTestingFramework_FIXTURE RobotTestingFramework_TEST)
    set(keywords ${flags} ${one} ${multi} ${groups})

    set(FIXTURE_elements "")
    set(TEST_elements "")
    set(mode "")        # the keyword whose values come next
    set(group_kind "")  # FIXTURE or TEST while inside a group
    set(group_file "")
    set(group_words "")
    set(group_type "")
    set(group_args "")
    set(arguments ${ARGN})
    list(APPEND arguments "<end>")  # closes the last group
    foreach(word IN LISTS arguments)
        set(keyword "")
        if(word IN_LIST keywords OR word STREQUAL "<end>")
            set(keyword "${word}")
        elseif(group_kind STREQUAL "TEST" AND (word STREQUAL "TYPE" OR word STREQUAL "ARGS"))
            set(keyword "${word}")
        endif()

        if(keyword AND NOT keyword STREQUAL "TYPE" AND NOT keyword STREQUAL "ARGS")
            if(mode IN_LIST one OR mode STREQUAL "TYPE" OR mode STREQUAL "GROUP_FILE")
                if(mode STREQUAL "GROUP_FILE")
                    message(FATAL_ERROR "${caller}(${arg_NAME}): ${group_keyword} needs a "
                                        "target or file")
                endif()
                message(FATAL_ERROR "${caller}(${arg_NAME}): ${mode} needs a value")
            endif()
            # A group ends at the next keyword of the function.
            if(group_kind)
                _robottestingframework_suite_elements("${caller}(${arg_NAME})" ${group_kind}
                    "${group_name}" "${group_file}" "${group_type}" "${group_words}"
                    "${group_args}" elements)
                string(APPEND ${group_kind}_elements "${elements}")
            endif()
            set(group_kind "")
            set(mode "${keyword}")
            if(keyword IN_LIST flags)
                set(arg_${keyword} TRUE)
                set(mode "")
            elseif(keyword IN_LIST groups)
                string(REPLACE "RobotTestingFramework_" "" group_kind "${keyword}")
                set(group_keyword "${keyword}")
                set(mode "GROUP_FILE")
                set(group_words "")
                set(group_type "")
                set(group_args "")
            endif()
        elseif(keyword AND mode STREQUAL "GROUP_FILE")
            message(FATAL_ERROR "${caller}(${arg_NAME}): RobotTestingFramework_TEST needs a "
                                "target or file before ${keyword}")
        elseif(keyword STREQUAL "TYPE")
            set(mode "TYPE")
        elseif(keyword STREQUAL "ARGS")
            set(mode "ARGS")
        elseif(mode STREQUAL "GROUP_FILE")
            set(group_name "${word}")
            _robottestingframework_plugin_file("${word}" group_file)
            set(mode "GROUP_WORDS")
        elseif(mode STREQUAL "GROUP_WORDS")
            list(APPEND group_words "${word}")
        elseif(mode STREQUAL "TYPE")
            set(group_type "${word}")
            set(mode "GROUP_WORDS")
        elseif(mode STREQUAL "ARGS")
            list(APPEND group_args "${word}")
        elseif(mode IN_LIST one)
            set(arg_${mode} "${word}")
            set(mode "")
        elseif(mode IN_LIST multi)
            list(APPEND arg_${mode} "${word}")
        else()
            message(FATAL_ERROR "${caller}(${arg_NAME}): unexpected argument \"${word}\"")
        endif()
    endforeach()

    if(NOT arg_NAME)
        message(FATAL_ERROR "${caller}: NAME is required (NAME name)")
    endif()
    if(TEST_elements STREQUAL "")
        message(FATAL_ERROR "${caller}(${arg_NAME}): no RobotTestingFramework_TEST (or SUITE "
                            "file.xml) given")
    endif()

    # One suite file per configuration with multi-configuration generators.
    string(REGEX REPLACE "[^A-Za-z0-9_.-]" "_" file_name "${arg_NAME}")
    get_property(multi_config GLOBAL PROPERTY GENERATOR_IS_MULTI_CONFIG)
    if(multi_config)
        set(suite_file "${CMAKE_CURRENT_BINARY_DIR}/${file_name}-$<CONFIG>.xml")
    else()
        set(suite_file "${CMAKE_CURRENT_BINARY_DIR}/${file_name}.xml")
    endif()
    _robottestingframework_xml_escape("${arg_NAME}" suite_name)
    string(CONCAT content "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                  "<suite name=\"${suite_name}\">\n${FIXTURE_elements}${TEST_elements}</suite>\n")
    file(GENERATE OUTPUT "${suite_file}" CONTENT "${content}")

    _robottestingframework_runner(runner)
    set(command "${runner}" --suite "${suite_file}")
    if(DEFINED arg_ENVIRONMENT)
        list(APPEND command --environment "${arg_ENVIRONMENT}")
    endif()
    if(arg_WEB_REPORTER)
        list(APPEND command --web-reporter)
    endif()
    if(arg_WEB_PORT)
        list(APPEND command --web-port "${arg_WEB_PORT}")
    endif()
    if(arg_DETAIL)
        list(APPEND command --detail)
    endif()
    if(arg_VERBOSE)
        list(APPEND command --verbose)
    endif()
    if(arg_OUTPUT_TYPE AND NOT arg_OUTPUT)
        # The runner's default file would land in the working folder, maybe the sources.
        if(arg_OUTPUT_TYPE STREQUAL "junit")
            set(arg_OUTPUT "${file_name}-result.xml")
        else()
            set(arg_OUTPUT "${file_name}-result.txt")
        endif()
    endif()
    if(arg_OUTPUT)
        if(NOT IS_ABSOLUTE "${arg_OUTPUT}")
            set(arg_OUTPUT "${CMAKE_CURRENT_BINARY_DIR}/${arg_OUTPUT}")
        endif()
        list(APPEND command --output "${arg_OUTPUT}")
        if(arg_OUTPUT_TYPE)
            list(APPEND command --output-type "${arg_OUTPUT_TYPE}")
        endif()
    elseif(NOT "-o" IN_LIST arg_RUNNER_ARGS AND NOT "--output" IN_LIST arg_RUNNER_ARGS)
        list(APPEND command --no-output)
    endif()
    list(APPEND command ${arg_RUNNER_ARGS})
    _robottestingframework_plugin_path_args("" plugin_path)
    list(APPEND command ${plugin_path})

    set(options "")
    if(arg_WORKING_DIRECTORY)
        list(APPEND options WORKING_DIRECTORY "${arg_WORKING_DIRECTORY}")
    endif()
    if(arg_CONFIGURATIONS)
        list(APPEND options CONFIGURATIONS ${arg_CONFIGURATIONS})
    endif()
    add_test(NAME "${arg_NAME}" COMMAND ${command} ${options} COMMAND_EXPAND_LISTS)
    _robottestingframework_test_properties()
endfunction()

# One CTest test per test of a suite file, listed when ctest starts (see the top of this file).
function(robottestingframework_discover_tests)
    set(caller robottestingframework_discover_tests)
    set(one SUITE NAME_PREFIX WORKING_DIRECTORY TIMEOUT DISCOVERY_TIMEOUT WORLD)
    set(multi RUNNER_ARGS PLUGIN_PATH TEST_ENVIRONMENT LABELS)
    cmake_parse_arguments(PARSE_ARGV 0 arg "" "${one}" "${multi}")
    if(arg_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR "${caller}: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
    endif()
    if(NOT arg_WORLD)
        set(arg_WORLD PER_SUITE)
    elseif(NOT arg_WORLD STREQUAL "PER_SUITE" AND NOT arg_WORLD STREQUAL "PER_TEST")
        message(FATAL_ERROR "${caller}: WORLD ${arg_WORLD}: expected PER_SUITE or PER_TEST")
    endif()
    if(WIN32)
        set(arg_WORLD PER_TEST)  # no world keeper on Windows
    endif()
    if(NOT arg_SUITE)
        message(FATAL_ERROR "${caller}: SUITE is required (SUITE file.xml)")
    endif()
    _robottestingframework_resolve_file("${arg_SUITE}" suite)
    if(NOT arg_WORKING_DIRECTORY)
        set(arg_WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
    endif()
    if(NOT arg_DISCOVERY_TIMEOUT)
        set(arg_DISCOVERY_TIMEOUT 60)
    endif()
    _robottestingframework_runner(runner)
    _robottestingframework_plugin_path_args("${arg_PLUGIN_PATH}" plugin_path)
    # Listing takes the runner's options (--var ...) but writes its own output; each test
    # writes none unless RUNNER_ARGS says where.
    set(list_args ${arg_RUNNER_ARGS})
    set(args ${arg_RUNNER_ARGS})
    if(NOT "-o" IN_LIST args AND NOT "--output" IN_LIST args)
        list(APPEND args --no-output)
    endif()

    # Each call its own files, even for one suite file given twice.
    get_property(count GLOBAL PROPERTY _ROBOTTESTINGFRAMEWORK_DISCOVERIES)
    if(NOT count)
        set(count 0)
    endif()
    math(EXPR count "${count} + 1")
    set_property(GLOBAL PROPERTY _ROBOTTESTINGFRAMEWORK_DISCOVERIES ${count})
    get_filename_component(suite_name "${suite}" NAME_WE)
    string(REGEX REPLACE "[^A-Za-z0-9_.-]" "_" suite_name "${suite_name}")
    set(base "${CMAKE_CURRENT_BINARY_DIR}/rtf_discover_${suite_name}_${count}")

    set(content "")
    foreach(variable runner suite args list_args plugin_path)
        _robottestingframework_bracket("${${variable}}" value)
        string(APPEND content "set(rtf_${variable} ${value})\n")
    endforeach()
    foreach(variable NAME_PREFIX WORKING_DIRECTORY TIMEOUT DISCOVERY_TIMEOUT TEST_ENVIRONMENT
                     LABELS WORLD)
        _robottestingframework_bracket("${arg_${variable}}" value)
        string(TOLOWER "${variable}" name)
        string(APPEND content "set(rtf_${name} ${value})\n")
    endforeach()
    _robottestingframework_bracket("${base}" value)
    string(APPEND content "set(rtf_base ${value})\n")
    # Where the keepers of shared worlds live: one folder for the whole build tree, so that
    # every discovery whose suites share a world finds the same keeper.
    _robottestingframework_bracket("${CMAKE_BINARY_DIR}/rtf_shared_worlds" value)
    string(APPEND content "set(rtf_shared_root ${value})\n")
    _robottestingframework_bracket("${_ROBOTTESTINGFRAMEWORK_DISCOVER_SCRIPT}" value)
    string(APPEND content "include(${value})\n")
    file(GENERATE OUTPUT "${base}_include.cmake" CONTENT "${content}")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${base}_include.cmake")
endfunction()
