# cmake [-DSRC_DIR=<folder>] -P check_arrows.cmake: fails, naming file and line, when a file of
# a folder of src/ includes a header of a folder it may not use (arrows.cmake), the public API
# (<robottestingframework/...>, core's) from below core, or anything through "../". The folders'
# targets already make most forbidden includes fail to compile; this also catches the ones a
# header lets through.
include(${CMAKE_CURRENT_LIST_DIR}/arrows.cmake)
if(NOT SRC_DIR)
    set(SRC_DIR ${CMAKE_CURRENT_LIST_DIR})
endif()

set(problems "")
foreach(folder IN LISTS RTF_SRC_FOLDERS)
    set(allowed ${folder} ${RTF_SRC_USES_${folder}})
    file(GLOB_RECURSE sources ${SRC_DIR}/${folder}/*.h ${SRC_DIR}/${folder}/*.cpp
         ${SRC_DIR}/${folder}/*.c ${SRC_DIR}/${folder}/*.in)
    foreach(source IN LISTS sources)
        file(STRINGS ${source} lines)
        set(number 0)
        foreach(line IN LISTS lines)
            math(EXPR number "${number} + 1")
            if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*[\"<]([^\">]+)[\">]")
                continue()
            endif()
            set(included ${CMAKE_MATCH_1})
            file(RELATIVE_PATH shown ${SRC_DIR} ${source})
            set(used "")
            if(included MATCHES "^robottestingframework/")
                set(used core)
            elseif(included MATCHES "^([^/]+)/")
                list(FIND RTF_SRC_FOLDERS ${CMAKE_MATCH_1} index)
                if(NOT index EQUAL -1)
                    set(used ${CMAKE_MATCH_1})
                endif()
            endif()
            if(used)
                list(FIND allowed ${used} index)
                if(index EQUAL -1)
                    string(REPLACE ";" ", " uses "${allowed}")
                    string(APPEND problems "${shown}:${number}: ${folder}/ may not include "
                           "${included} (it may use: ${uses})\n")
                endif()
            elseif(included MATCHES "\\.\\./")
                string(APPEND problems "${shown}:${number}: ${included}: include by module "
                       "path, not through ../\n")
            endif()
        endforeach()
    endforeach()
endforeach()

if(problems)
    # Printed as is (FATAL_ERROR would wrap the lines), one per include.
    message(NOTICE "${problems}")
    message(FATAL_ERROR "forbidden includes: see src/README.md")
endif()
