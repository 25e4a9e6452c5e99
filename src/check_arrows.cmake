# cmake [-DSCOPE=runner] [-DDIR=<folder>] -P check_arrows.cmake: fails, naming file and line,
# when a file includes a header of a folder it may not use, or anything through "../".
#   - SCOPE src (the default): the folders of src/ (arrows.cmake); the public API
#     (<robottestingframework/...>) is core's, so it may not be included below core;
#   - SCOPE runner: the folders of src/runner/ (runner/arrows.cmake), whose headers are
#     included by module path ("runner/<folder>/x.h"), never by their bare name.
# DIR is the tree checked (the scope's own folder unless given; the tests give others). The
# folders' targets already make most forbidden includes fail to compile; this also catches the
# ones a header lets through (runner's console sees plan's headers because the scheduler's header
# includes one, yet may not include them itself).
if(SCOPE STREQUAL "runner")
    include(${CMAKE_CURRENT_LIST_DIR}/runner/arrows.cmake)
    set(folders ${RTF_RUNNER_FOLDERS})
    set(uses RTF_RUNNER_USES_)
    set(module "^runner/([^/]+)/")
    set(readme src/runner/README.md)
    set(own_dir ${CMAKE_CURRENT_LIST_DIR}/runner)
    # The runner's headers by their bare names, which may not be included so.
    file(GLOB_RECURSE headers RELATIVE ${own_dir} ${own_dir}/*.h)
    set(bare_names "")
    foreach(header IN LISTS headers)
        get_filename_component(name ${header} NAME)
        list(APPEND bare_names ${name})
    endforeach()
else()
    include(${CMAKE_CURRENT_LIST_DIR}/arrows.cmake)
    set(folders ${RTF_SRC_FOLDERS})
    set(uses RTF_SRC_USES_)
    set(module "^([^/]+)/")
    set(readme src/README.md)
    set(own_dir ${CMAKE_CURRENT_LIST_DIR})
    set(bare_names "")
endif()
if(NOT DIR)
    set(DIR ${own_dir})
endif()

set(problems "")
foreach(folder IN LISTS folders)
    set(allowed ${folder} ${${uses}${folder}})
    file(GLOB_RECURSE sources ${DIR}/${folder}/*.h ${DIR}/${folder}/*.cpp ${DIR}/${folder}/*.c
         ${DIR}/${folder}/*.in)
    foreach(source IN LISTS sources)
        file(STRINGS ${source} lines)
        set(number 0)
        foreach(line IN LISTS lines)
            math(EXPR number "${number} + 1")
            if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*[\"<]([^\">]+)[\">]")
                continue()
            endif()
            set(included ${CMAKE_MATCH_1})
            file(RELATIVE_PATH shown ${DIR} ${source})
            set(used "")
            if(NOT SCOPE STREQUAL "runner" AND included MATCHES "^robottestingframework/")
                set(used core)
            elseif(included MATCHES "${module}")
                list(FIND folders ${CMAKE_MATCH_1} index)
                if(NOT index EQUAL -1)
                    set(used ${CMAKE_MATCH_1})
                endif()
            endif()
            list(FIND bare_names ${included} bare)
            if(used)
                list(FIND allowed ${used} index)
                if(index EQUAL -1)
                    string(REPLACE ";" ", " may "${allowed}")
                    string(APPEND problems "${shown}:${number}: ${folder}/ may not include "
                           "${included} (it may use: ${may})\n")
                endif()
            elseif(included MATCHES "\\.\\./")
                string(APPEND problems "${shown}:${number}: ${included}: include by module "
                       "path, not through ../\n")
            elseif(NOT bare EQUAL -1 AND line MATCHES "\"")
                string(APPEND problems "${shown}:${number}: ${included}: include runner "
                       "headers by their module path (\"runner/<folder>/${included}\")\n")
            endif()
        endforeach()
    endforeach()
endforeach()

if(problems)
    # Printed as is (FATAL_ERROR would wrap the lines), one per include.
    message(NOTICE "${problems}")
    message(FATAL_ERROR "forbidden includes: see ${readme}")
endif()
