# The Windows build's dependencies (cmake/mingw-w64.cmake), from what scripts/windows-deps.sh
# put in <build dir>/deps/, under the names find_package gives them on Linux, so the project's
# CMake files link them the same way:
#   pugixml::pugixml   pugixml from Debian's source package, a static library
#   rtf_lua            Lua 5.4 from Debian's source package, a static library (its C API)
#   httplib::httplib   cpp-httplib's header-only httplib.h, from Debian's source package
#   SQLite::SQLite3    SQLite, a static library from the amalgamation scripts/windows-deps.sh
#                      generates from Debian's source package (so no DLL to ship)
#   re2::re2           RE2 from Debian's source package and the tables scripts/windows-deps.sh
#                      generates from it, a static library
#   CLI11::CLI11, nlohmann_json::nlohmann_json   the copied headers
#   GTest::gtest, GTest::gtest_main   GoogleTest built from /usr/src/googletest
set(RTF_WINDOWS_DEPS_DIR ${PROJECT_BINARY_DIR}/deps CACHE PATH
    "Where scripts/windows-deps.sh put the Windows build's third-party sources and headers")

# <name>: the one folder matching <pattern> under the deps folder, or a clear error.
function(rtf_windows_dep_folder name pattern)
    file(GLOB found LIST_DIRECTORIES true ${RTF_WINDOWS_DEPS_DIR}/${pattern})
    list(FILTER found EXCLUDE REGEX "\\.(tar\\..*|dsc)$")
    if(NOT found)
        message(FATAL_ERROR "${RTF_WINDOWS_DEPS_DIR}/${pattern} is missing: run "
                            "scripts/windows-deps.sh ${PROJECT_BINARY_DIR} (./run.sh windows does)")
    endif()
    list(GET found 0 folder)
    set(${name} ${folder} PARENT_SCOPE)
endfunction()

rtf_windows_dep_folder(pugixml_dir pugixml-*)
add_library(rtf_pugixml STATIC ${pugixml_dir}/src/pugixml.cpp)
target_include_directories(rtf_pugixml SYSTEM PUBLIC ${pugixml_dir}/src)
add_library(pugixml::pugixml ALIAS rtf_pugixml)

rtf_windows_dep_folder(lua_dir lua5.4-*)
file(GLOB lua_sources ${lua_dir}/src/*.c)
# The interpreter's and the compiler's programs, not the library.
list(FILTER lua_sources EXCLUDE REGEX "/(lua|luac)\\.c$")
add_library(rtf_lua STATIC ${lua_sources})
target_include_directories(rtf_lua SYSTEM PUBLIC ${lua_dir}/src)
# Third-party C code: built with its own warnings, not ours.
target_compile_options(rtf_lua PRIVATE -w)

set(sqlite_dir ${RTF_WINDOWS_DEPS_DIR}/sqlite3-amalgamation)
if(NOT EXISTS ${sqlite_dir}/sqlite3.c OR NOT EXISTS ${sqlite_dir}/sqlite3.h)
    message(FATAL_ERROR "${sqlite_dir} lacks sqlite3.c or sqlite3.h: run "
                        "scripts/windows-deps.sh ${PROJECT_BINARY_DIR}")
endif()
add_library(rtf_sqlite3 STATIC ${sqlite_dir}/sqlite3.c)
target_include_directories(rtf_sqlite3 SYSTEM PUBLIC ${sqlite_dir})
# Thread-safe as Debian's libsqlite3 is, so the history behaves as on Linux; no run-time
# extension loading (the runner loads none).
target_compile_definitions(rtf_sqlite3 PRIVATE SQLITE_THREADSAFE=1 SQLITE_OMIT_LOAD_EXTENSION)
# Third-party C code: built with its own warnings, not ours.
target_compile_options(rtf_sqlite3 PRIVATE -w)
add_library(SQLite::SQLite3 ALIAS rtf_sqlite3)

# RE2's library sources, as its CMakeLists.txt lists them; three of them are the generated tables.
rtf_windows_dep_folder(re2_dir re2-*)
set(re2_tables ${RTF_WINDOWS_DEPS_DIR}/re2-tables/re2)
if(NOT EXISTS ${re2_tables}/unicode_groups.cc)
    message(FATAL_ERROR "${re2_tables} lacks RE2's tables: run "
                        "scripts/windows-deps.sh ${PROJECT_BINARY_DIR}")
endif()
set(re2_sources)
foreach(name bitstate compile dfa filtered_re2 mimics_pcre nfa onepass parse prefilter
             prefilter_tree prog re2 regexp set simplify stringpiece tostring)
    list(APPEND re2_sources ${re2_dir}/re2/${name}.cc)
endforeach()
add_library(rtf_re2 STATIC ${re2_sources} ${re2_dir}/util/rune.cc ${re2_dir}/util/strutil.cc
            ${re2_tables}/perl_groups.cc ${re2_tables}/unicode_casefold.cc
            ${re2_tables}/unicode_groups.cc)
target_include_directories(rtf_re2 SYSTEM PUBLIC ${re2_dir})
# Third-party code: built with its own warnings, not ours.
target_compile_options(rtf_re2 PRIVATE -w)
add_library(re2::re2 ALIAS rtf_re2)

set(header_dir ${RTF_WINDOWS_DEPS_DIR}/include)
if(NOT EXISTS ${header_dir}/CLI/CLI.hpp OR NOT EXISTS ${header_dir}/nlohmann/json.hpp)
    message(FATAL_ERROR "${header_dir} lacks CLI11 or nlohmann-json: run "
                        "scripts/windows-deps.sh ${PROJECT_BINARY_DIR}")
endif()
foreach(name CLI11::CLI11 nlohmann_json::nlohmann_json)
    string(REPLACE "::" "_" target rtf_${name})
    add_library(${target} INTERFACE)
    target_include_directories(${target} SYSTEM INTERFACE ${header_dir})
    add_library(${name} ALIAS ${target})
endforeach()

# Over Winsock (ws2_32), which its header asks for with a pragma MinGW ignores.
rtf_windows_dep_folder(httplib_dir cpp-httplib-*)
add_library(rtf_httplib INTERFACE)
target_include_directories(rtf_httplib SYSTEM INTERFACE ${httplib_dir})
target_link_libraries(rtf_httplib INTERFACE ws2_32)
add_library(httplib::httplib ALIAS rtf_httplib)

if(RTF_BUILD_TESTS)
    set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
    set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
    add_subdirectory(/usr/src/googletest ${PROJECT_BINARY_DIR}/googletest EXCLUDE_FROM_ALL)
    add_library(GTest::gtest ALIAS gtest)
    add_library(GTest::gtest_main ALIAS gtest_main)
endif()

find_package(Threads REQUIRED)

# MinGW-w64's run-time DLLs (C++ library, unwinder, threads), beside the programs as a Windows
# installation ships them: one copy of each for the runner, the library and the plug-ins, so
# exceptions and objects cross DLL boundaries as they do between shared objects on Linux.
execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libstdc++-6.dll
                OUTPUT_VARIABLE libstdcxx_dll OUTPUT_STRIP_TRAILING_WHITESPACE)
execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libgcc_s_seh-1.dll
                OUTPUT_VARIABLE libgcc_dll OUTPUT_STRIP_TRAILING_WHITESPACE)
find_file(RTF_WINPTHREAD_DLL libwinpthread-1.dll PATHS /usr/${RTF_MINGW_PREFIX}/lib
          NO_DEFAULT_PATH)
foreach(dll ${libstdcxx_dll} ${libgcc_dll} ${RTF_WINPTHREAD_DLL})
    if(NOT IS_ABSOLUTE ${dll} OR NOT EXISTS ${dll})
        message(FATAL_ERROR "MinGW-w64's run-time DLL ${dll} is missing "
                            "(g++-mingw-w64-x86-64-posix)")
    endif()
    file(COPY ${dll} DESTINATION ${CMAKE_RUNTIME_OUTPUT_DIRECTORY})
    # The installed programs import them too (x86_64-w64-mingw32-objdump -p): in bin/ as well.
    install(FILES ${dll} DESTINATION ${CMAKE_INSTALL_BINDIR})
endforeach()
