# Run by ctest when it starts (the TEST_INCLUDE_FILES of robottestingframework_discover_tests,
# RobotTestingFrameworkCTest.cmake): lists the suite's tests with the runner and registers one
# CTest test per test id. The calling file sets rtf_runner, rtf_suite, rtf_args (each test's),
# rtf_list_args (the listing's), rtf_plugin_path, rtf_name_prefix, rtf_working_directory,
# rtf_timeout, rtf_discovery_timeout, rtf_test_environment, rtf_labels, rtf_world (PER_SUITE or
# PER_TEST) and rtf_base (where this script writes its files).
#
# WORLD PER_SUITE (the default where the runner has a world keeper, not on Windows): a suite
# with fixtures gets a test <prefix><suite>/world:up (FIXTURES_SETUP: --world-up DIR sets its
# fixtures up once, in a keeper process) and <prefix><suite>/world:down (FIXTURES_CLEANUP:
# --world-down DIR), and each of its tests runs with --world DIR (FIXTURES_REQUIRED) in that
# world. Every test of a suite, world tests included, takes the suite's RESOURCE_LOCK, so that
# they never run at once, as in one run of the suite. docs/how-to/ctest-worlds.md.
#
# Shared worlds (<fixture type="process" scope="run">): a suite whose fixtures are all shared
# worlds has no world of its own; its tests run with --world DIR in the keeper of those worlds,
# which every discovery of the build tree whose suites need the same worlds shares: one CTest
# fixture rtf_shared_world_<hash> with the tests world:<name>:up and world:<name>:down, its
# keeper in rtf_shared_root/<hash> (hash: the worlds' identities, file and param). The first
# discovery that names them registers them (a global property); the keeper's suite file
# (<hash>.xml) holds the worlds, in a private network when any of their suites asks for one.
# rtf_shared_root comes from the calling file. docs/how-to/ctest-shared-worlds.md.
if(CMAKE_VERSION VERSION_LESS 3.19)
    message(FATAL_ERROR "robottestingframework_discover_tests needs ctest 3.19 or later "
                        "(string(JSON)); this is ${CMAKE_VERSION}")
endif()

include("${CMAKE_CURRENT_LIST_DIR}/RobotTestingFrameworkBracket.cmake")

# The --filter pattern that selects the test `id` alone. The runner takes an id written as it
# is listed; should GoogleTest's pattern characters (* ? : -) ever need escaping, it is here.
function(_rtf_filter_pattern id out)
    set(${out} "${id}" PARENT_SCOPE)
endfunction()

# The runner's exit status for --world-down of a world that never started (its world:up failed
# and is the one test that counts the failure): CTest says the world:down test was skipped.
set(rtf_world_never_started 77)

# One add_test and its properties, as text for the generated file.
function(_rtf_test_text name command out)
    set(text "add_test(")
    foreach(word IN LISTS name command)
        _robottestingframework_bracket("${word}" quoted)
        string(APPEND text " ${quoted}")
    endforeach()
    _robottestingframework_bracket("${name}" quoted_name)
    _robottestingframework_bracket("${rtf_working_directory}" directory)
    string(APPEND text ")\nset_tests_properties(${quoted_name} PROPERTIES WORKING_DIRECTORY "
                       "${directory}")
    if(rtf_timeout)
        string(APPEND text " TIMEOUT ${rtf_timeout}")
    endif()
    if(rtf_test_environment)
        _robottestingframework_bracket("${rtf_test_environment}" environment)
        string(APPEND text " ENVIRONMENT ${environment}")
    endif()
    if(ARGN)
        _robottestingframework_bracket("${ARGN}" labels)
        string(APPEND text " LABELS ${labels}")
    endif()
    # The suite's lock and world fixture (_rtf_world_properties), when set.
    foreach(property RESOURCE_LOCK FIXTURES_SETUP FIXTURES_CLEANUP FIXTURES_REQUIRED
                     SKIP_RETURN_CODE)
        if(rtf_${property})
            _robottestingframework_bracket("${rtf_${property}}" value)
            string(APPEND text " ${property} ${value}")
        endif()
    endforeach()
    set(${out} "${text})\n" PARENT_SCOPE)
endfunction()

# Text for XML (an attribute's value or an element's text).
function(_rtf_xml_escape text out)
    string(REPLACE "&" "&amp;" text "${text}")
    string(REPLACE "<" "&lt;" text "${text}")
    string(REPLACE ">" "&gt;" text "${text}")
    string(REPLACE "\"" "&quot;" text "${text}")
    set(${out} "${text}" PARENT_SCOPE)
endfunction()

# The shared worlds of suite `s` of the listing: sets shared_fixture, shared_dir and
# shared_tests (the world:up and world:down tests' text, empty when an earlier discovery
# registered them) in the caller's scope, and own_fixtures (TRUE when the suite has fixtures of
# its own besides: its keeper then joins the shared one with --shared-worlds). shared_fixture
# is empty when the suite has no shared world.
function(_rtf_shared_worlds listing s)
    set(shared_fixture "" PARENT_SCOPE)
    set(shared_tests "" PARENT_SCOPE)
    set(own_fixtures FALSE PARENT_SCOPE)
    string(JSON count LENGTH "${listing}" suites ${s} fixtures)
    math(EXPR last "${count} - 1")
    set(identities "")
    set(names "")
    set(fixtures_xml "")
    foreach(f RANGE ${last})
        string(JSON scope ERROR_VARIABLE no_scope GET "${listing}" suites ${s} fixtures ${f} scope)
        if(no_scope OR NOT scope STREQUAL "run")
            set(own_fixtures TRUE PARENT_SCOPE)
            continue()
        endif()
        string(JSON identity GET "${listing}" suites ${s} fixtures ${f} identity)
        string(JSON name GET "${listing}" suites ${s} fixtures ${f} world)
        string(JSON file GET "${listing}" suites ${s} fixtures ${f} world_file)
        string(JSON param GET "${listing}" suites ${s} fixtures ${f} param)
        string(APPEND identities "${identity}\n")
        list(APPEND names "${name}")
        _rtf_xml_escape("${file}" file)
        _rtf_xml_escape("${param}" param)
        string(APPEND fixtures_xml
               "  <fixture type=\"process\" param=\"${param}\">${file}</fixture>\n")
    endforeach()
    if(NOT names)
        return()
    endif()
    string(MD5 hash "${identities}")
    string(SUBSTRING "${hash}" 0 12 hash)
    list(JOIN names "+" name)
    set(fixture "rtf_shared_world_${hash}")
    set(dir "${rtf_shared_root}/${hash}")
    set(shared_fixture "${fixture}" PARENT_SCOPE)
    set(shared_dir "${dir}" PARENT_SCOPE)
    string(JSON network ERROR_VARIABLE no_network GET "${listing}" suites ${s} network)
    if(no_network OR NOT network STREQUAL "private")
        set(network "host")
    endif()
    get_property(registered GLOBAL PROPERTY "_rtf_shared_world_${hash}")
    get_property(private GLOBAL PROPERTY "_rtf_shared_world_${hash}_private")
    if(registered AND (private OR network STREQUAL "host"))
        return()
    endif()
    # The keeper's suite: the worlds alone (their params with every variable filled in).
    _rtf_xml_escape("${name}" suite_name)
    set(attributes "")
    if(network STREQUAL "private")
        set(attributes " network=\"private\"")
        set_property(GLOBAL PROPERTY "_rtf_shared_world_${hash}_private" TRUE)
    endif()
    file(WRITE "${rtf_shared_root}/${hash}.xml"
         "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<!-- Written by RobotTestingFrameworkDiscoverTests.cmake: the keeper of shared "
         "worlds for the suites of ctest that need them. -->\n"
         "<suite name=\"shared world ${suite_name}\"${attributes}>\n${fixtures_xml}</suite>\n")
    if(registered)
        return()
    endif()
    set_property(GLOBAL PROPERTY "_rtf_shared_world_${hash}" TRUE)
    # Two sets of worlds of one name (another file or param): the second gets its hash.
    get_property(named GLOBAL PROPERTY "_rtf_shared_world_name_${name}")
    if(named AND NOT named STREQUAL hash)
        set(name "${name}@${hash}")
    else()
        set_property(GLOBAL PROPERTY "_rtf_shared_world_name_${name}" "${hash}")
    endif()
    set(rtf_RESOURCE_LOCK "")
    set(rtf_FIXTURES_REQUIRED "")
    set(rtf_FIXTURES_CLEANUP "")
    set(rtf_FIXTURES_SETUP "${fixture}")
    set(command "${rtf_runner}" --suite "${rtf_shared_root}/${hash}.xml" --world-up "${dir}"
                ${rtf_plugin_path} ${rtf_args})
    _rtf_test_text("world:${name}:up" "${command}" up ${rtf_labels})
    set(rtf_FIXTURES_SETUP "")
    set(rtf_FIXTURES_CLEANUP "${fixture}")
    set(rtf_SKIP_RETURN_CODE ${rtf_world_never_started})
    set(command "${rtf_runner}" --suite "${rtf_shared_root}/${hash}.xml" --world-down "${dir}"
                ${rtf_plugin_path} ${rtf_args})
    _rtf_test_text("world:${name}:down" "${command}" down ${rtf_labels})
    set(rtf_SKIP_RETURN_CODE "")
    set(shared_tests "${up}${down}" PARENT_SCOPE)
endfunction()

set(rtf_list_file "${rtf_base}_list.json")
file(REMOVE "${rtf_list_file}")
execute_process(
    COMMAND "${rtf_runner}" --suite "${rtf_suite}" --list --output "json:${rtf_list_file}"
            ${rtf_plugin_path} ${rtf_list_args}
    WORKING_DIRECTORY "${rtf_working_directory}"
    RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output
    TIMEOUT ${rtf_discovery_timeout})

set(generated "# Generated by RobotTestingFrameworkDiscoverTests.cmake from ${rtf_suite}\n")
if(NOT status EQUAL 0 OR NOT EXISTS "${rtf_list_file}")
    # A test that fails with the runner's own message, so `ctest` shows why.
    get_filename_component(file_name "${rtf_suite}" NAME)
    set(command "${rtf_runner}" --suite "${rtf_suite}" --list ${rtf_plugin_path}
                ${rtf_list_args})
    _rtf_test_text("${rtf_name_prefix}${file_name}/list" "${command}" text)
    string(APPEND generated "${text}")
else()
    file(READ "${rtf_list_file}" listing)
    string(JSON suites LENGTH "${listing}" suites)
    if(suites GREATER 0)
        math(EXPR last_suite "${suites} - 1")
        foreach(s RANGE ${last_suite})
            string(JSON tests LENGTH "${listing}" suites ${s} tests)
            if(tests EQUAL 0)
                continue()
            endif()
            # The suite's tests never run at once; a suite with fixtures starts them once.
            string(JSON suite_name GET "${listing}" suites ${s} name)
            set(rtf_RESOURCE_LOCK "rtf_suite:${rtf_suite}")
            set(rtf_FIXTURES_SETUP "")
            set(rtf_FIXTURES_CLEANUP "")
            set(rtf_FIXTURES_REQUIRED "")
            set(world_args "")
            string(JSON fixture_count LENGTH "${listing}" suites ${s} fixtures)
            set(shared_fixture "")
            set(shared_args "")
            if(rtf_world STREQUAL "PER_SUITE" AND fixture_count GREATER 0 AND suites EQUAL 1)
                _rtf_shared_worlds("${listing}" ${s})
                string(APPEND generated "${shared_tests}")
            endif()
            if(shared_fixture AND NOT own_fixtures)
                # Shared worlds alone: the tests run in their keeper, shared with other suites.
                set(rtf_FIXTURES_REQUIRED "${shared_fixture}")
                set(world_args --world "${shared_dir}")
            elseif(rtf_world STREQUAL "PER_SUITE" AND fixture_count GREATER 0 AND suites EQUAL 1)
                if(shared_fixture)
                    # Fixtures of its own besides: its keeper joins the shared worlds' keeper.
                    set(shared_args --shared-worlds "${shared_dir}")
                    set(rtf_FIXTURES_REQUIRED "${shared_fixture}")
                endif()
                # A CTest fixture name is global: the discovery's folder and number make it unique.
                string(MD5 world_hash "${rtf_base}")
                string(SUBSTRING "${world_hash}" 0 12 world_hash)
                set(world_fixture "rtf_world_${world_hash}")
                set(world_dir "${rtf_base}_world")
                set(rtf_FIXTURES_SETUP "${world_fixture}")
                set(command "${rtf_runner}" --suite "${rtf_suite}" --world-up "${world_dir}"
                            ${shared_args} ${rtf_plugin_path} ${rtf_args})
                _rtf_test_text("${rtf_name_prefix}${suite_name}/world:up" "${command}" text
                               ${rtf_labels})
                string(APPEND generated "${text}")
                set(rtf_FIXTURES_SETUP "")
                set(rtf_FIXTURES_CLEANUP "${world_fixture}")
                set(rtf_SKIP_RETURN_CODE ${rtf_world_never_started})
                set(command "${rtf_runner}" --suite "${rtf_suite}" --world-down "${world_dir}"
                            ${rtf_plugin_path} ${rtf_args})
                _rtf_test_text("${rtf_name_prefix}${suite_name}/world:down" "${command}" text
                               ${rtf_labels})
                set(rtf_SKIP_RETURN_CODE "")
                string(APPEND generated "${text}")
                set(rtf_FIXTURES_CLEANUP "")
                list(APPEND rtf_FIXTURES_REQUIRED "${world_fixture}")
                set(world_args --world "${world_dir}")
            endif()
            math(EXPR last_test "${tests} - 1")
            foreach(t RANGE ${last_test})
                string(JSON id GET "${listing}" suites ${s} tests ${t} id)
                set(labels ${rtf_labels})
                string(JSON tag_count LENGTH "${listing}" suites ${s} tests ${t} tags)
                if(tag_count GREATER 0)
                    math(EXPR last_tag "${tag_count} - 1")
                    foreach(g RANGE ${last_tag})
                        string(JSON tag GET "${listing}" suites ${s} tests ${t} tags ${g})
                        list(APPEND labels "${tag}")
                    endforeach()
                endif()
                _rtf_filter_pattern("${id}" pattern)
                set(command "${rtf_runner}" --suite "${rtf_suite}" --filter "${pattern}"
                            ${world_args} ${rtf_plugin_path} ${rtf_args})
                _rtf_test_text("${rtf_name_prefix}${id}" "${command}" text ${labels})
                string(APPEND generated "${text}")
            endforeach()
        endforeach()
    endif()
endif()
file(WRITE "${rtf_base}_tests.cmake" "${generated}")
include("${rtf_base}_tests.cmake")
