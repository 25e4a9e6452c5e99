# cmake [-DSRC_DIR=<dir>] [-DMAX_FILES=<n>] -P check_kind_spelling.cmake: fails when more than
# MAX_FILES (4) files of SRC_DIR (src/) spell a member of ResultEvent::Kind (`Kind::Report`,
# `ResultEvent::Kind::EndTest`, ...). What a kind is lives in one table (src/core/TestStatus.cpp),
# events are made by name beside it (src/core/events.h), and RTF 2.x's adapter
# (src/core/TestListener.cpp) turns them into the named handlers: every other file asks the
# table (docs/development/event-kinds.md). Another enum's members of the same names
# (ReadyCheck::Kind::Output) are not counted.
if(NOT SRC_DIR)
    get_filename_component(SRC_DIR "${CMAKE_CURRENT_LIST_DIR}/../../src" ABSOLUTE)
endif()
if(NOT MAX_FILES)
    set(MAX_FILES 4)
endif()
set(kinds "StartRunner|EndRunner|StartSuite|EndSuite|StartTest|EndTest|Report|Check|Failure")
string(APPEND kinds "|Error|Skipped|Crash|Timeout|Interrupted|Output|Rename|Retry|Repetition")
string(APPEND kinds "|Measurement|Attachment|World|Probe")
set(spelled "(^|ResultEvent::|[^:A-Za-z0-9_])Kind::(${kinds})([^A-Za-z0-9_]|$)")
file(GLOB_RECURSE sources RELATIVE "${SRC_DIR}" "${SRC_DIR}/*.cpp" "${SRC_DIR}/*.h"
     "${SRC_DIR}/*.hpp" "${SRC_DIR}/*.c" "${SRC_DIR}/*.cc")
list(SORT sources)
set(spelling "")
foreach(source IN LISTS sources)
    file(STRINGS "${SRC_DIR}/${source}" lines REGEX "${spelled}")
    if(lines)
        list(APPEND spelling "${source}")
    endif()
endforeach()
list(LENGTH spelling count)
string(REPLACE ";" "\n  " shown "${spelling}")
if(count GREATER MAX_FILES)
    message(FATAL_ERROR "${count} files of ${SRC_DIR} spell ResultEvent::Kind members (at most "
                        "${MAX_FILES}: the table, the makers, RTF 2.x's adapter; the others ask "
                        "the table, docs/development/event-kinds.md):\n  ${shown}")
endif()
message(STATUS "${count} files of ${SRC_DIR} spell ResultEvent::Kind members (at most "
               "${MAX_FILES}):\n  ${shown}")
