# Cross-building for 64-bit Windows with Debian's MinGW-w64 (g++-mingw-w64-x86-64-posix: the
# "posix" flavour has std::thread and std::mutex). ./run.sh windows uses it for build-windows/
# and runs what it builds under Wine (CMAKE_CROSSCOMPILING_EMULATOR, so ctest runs the tests
# through wine64 as it would run them natively).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)

set(RTF_MINGW_PREFIX x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${RTF_MINGW_PREFIX}-gcc-posix)
set(CMAKE_CXX_COMPILER ${RTF_MINGW_PREFIX}-g++-posix)
set(CMAKE_RC_COMPILER ${RTF_MINGW_PREFIX}-windres)

# Libraries and headers come from the MinGW sysroot and from what the build makes; programs
# (python3, cmake's own tools) from the build machine.
set(CMAKE_FIND_ROOT_PATH /usr/${RTF_MINGW_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Debian's wine64 package puts the loader in /usr/lib/wine; wine64 on PATH only with the
# "wine" package.
find_program(RTF_WINE64 NAMES wine64 PATHS /usr/lib/wine NO_DEFAULT_PATH)
find_program(RTF_WINE64 NAMES wine64)
if(RTF_WINE64)
    set(CMAKE_CROSSCOMPILING_EMULATOR ${RTF_WINE64})
endif()
