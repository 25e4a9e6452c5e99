# cmake -DRUNNER_DIR=<folder> -P check_arrows.cmake: fails, naming file and line, when a file of
# a runner folder includes a runner header it may not use (arrows.cmake), a runner header by
# its bare name, or anything through "../". The folders' targets already make most forbidden
# includes fail to compile; this also catches the ones a header lets through (console sees
# plan's headers because the scheduler's header includes one, yet may not include them itself).
include(${CMAKE_CURRENT_LIST_DIR}/arrows.cmake)
if(NOT RUNNER_DIR)
    set(RUNNER_DIR ${CMAKE_CURRENT_LIST_DIR})
endif()

file(GLOB_RECURSE runner_headers RELATIVE ${CMAKE_CURRENT_LIST_DIR} ${CMAKE_CURRENT_LIST_DIR}/*.h)
set(bare_names "")
foreach(header IN LISTS runner_headers)
    get_filename_component(name ${header} NAME)
    list(APPEND bare_names ${name})
endforeach()

set(problems "")
foreach(folder IN LISTS RTF_RUNNER_FOLDERS)
    set(allowed ${folder} ${RTF_RUNNER_USES_${folder}})
    file(GLOB_RECURSE sources ${RUNNER_DIR}/${folder}/*.h ${RUNNER_DIR}/${folder}/*.cpp)
    foreach(source IN LISTS sources)
        file(STRINGS ${source} lines)
        set(number 0)
        foreach(line IN LISTS lines)
            math(EXPR number "${number} + 1")
            if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\"")
                continue()
            endif()
            set(included ${CMAKE_MATCH_1})
            file(RELATIVE_PATH shown ${RUNNER_DIR} ${source})
            if(included MATCHES "^runner/([^/]+)/")
                list(FIND allowed ${CMAKE_MATCH_1} index)
                if(index EQUAL -1)
                    string(REPLACE ";" ", " uses "${allowed}")
                    string(APPEND problems "${shown}:${number}: ${folder}/ may not include "
                           "${included} (it may use: ${uses})\n")
                endif()
            elseif(included MATCHES "\\.\\./")
                string(APPEND problems "${shown}:${number}: ${included}: include by module "
                       "path, not through ../\n")
            else()
                list(FIND bare_names ${included} index)
                if(NOT index EQUAL -1)
                    string(APPEND problems "${shown}:${number}: ${included}: include runner "
                           "headers by their module path (\"runner/<folder>/${included}\")\n")
                endif()
            endif()
        endforeach()
    endforeach()
endforeach()

if(problems)
    # Printed as is (FATAL_ERROR would wrap the lines), one per include.
    message(NOTICE "${problems}")
    message(FATAL_ERROR "forbidden includes: see src/runner/README.md")
endif()
