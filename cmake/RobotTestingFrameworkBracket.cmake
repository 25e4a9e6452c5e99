# robottestingframework_bracket(TEXT OUT): OUT is a bracket argument holding TEXT as is, for a
# generated CMake file. Shared by RobotTestingFrameworkCTest.cmake (at configure time) and
# RobotTestingFrameworkDiscoverTests.cmake (run by ctest), which sit beside this file.
include_guard(GLOBAL)

function(_robottestingframework_bracket text out)
    set(equals "=")
    while("${text}" MATCHES "]${equals}]")
        string(APPEND equals "=")
    endwhile()
    set(${out} "[${equals}[${text}]${equals}]" PARENT_SCOPE)
endfunction()
