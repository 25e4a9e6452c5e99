#!/usr/bin/env bash
# windows-deps.sh BUILD_DIR: the third-party code the Windows build (cmake/mingw-w64.cmake)
# compiles or includes, fetched into BUILD_DIR/deps/ and never into the repository:
#   - pugixml, Lua 5.4, cpp-httplib, SQLite and RE2: Debian 12's source packages (`apt-get source`;
#     Debian's installed httplib.h declares only, its code being in libcpp-httplib.so, while the
#     source has the header-only httplib.h the Windows build compiles), through an apt
#     configuration of its own under BUILD_DIR/deps/apt/ (its sources.list with deb-src lines,
#     its lists and caches): the machine's /etc/apt and /var/lib/apt are never written;
#   - SQLite's amalgamation (sqlite3.c, sqlite3.h): Debian's source is SQLite's full tree, so it
#     is generated from it with the native tools (./configure, make sqlite3.c: tclsh), in
#     BUILD_DIR/deps/sqlite3-amalgamation/, which the Windows build cross-compiles;
#   - RE2's generated tables (perl_groups.cc, unicode_casefold.cc, unicode_groups.cc): Debian's
#     source leaves them out (debian/copyright, Files-Excluded) and makes them when it builds,
#     from the Unicode data of the unicode-data package (python3, python3-six, perl); they are
#     generated the same way into BUILD_DIR/deps/re2-tables/re2/;
#   - CLI11 and nlohmann-json: the headers Debian installed, copied alone into
#     BUILD_DIR/deps/include/, so the cross compiler never sees /usr/include (glibc's headers).
# Quick when done: each part is fetched (and SQLite's amalgamation generated) once.
set -euo pipefail
[[ $# -eq 1 ]] || {
    echo "usage: $0 BUILD_DIR" >&2
    exit 2
}
mkdir -p "$1/deps"
deps=$(cd "$1/deps" && pwd)

# The header-only libraries, as installed by scripts/install-deps.sh.
mkdir -p "$deps/include"
for header in /usr/include/CLI /usr/include/nlohmann; do
    if [[ ! -e "$header" ]]; then
        echo "windows-deps: $header is missing (scripts/install-deps.sh installs it)" >&2
        exit 1
    fi
    cp -a "$header" "$deps/include/"
done

# Installed httplib.h copied here by earlier versions of this script: not the one to compile.
rm -f "$deps/include/httplib.h"

# Source packages: their name, and the folder `apt-get source` unpacks them to.
packages=(pugixml lua5.4 cpp-httplib sqlite3 re2)
folders=("pugixml-*/src/pugixml.cpp" "lua5.4-*/src/lua.h" "cpp-httplib-*/httplib.h"
    "sqlite3-*/tool/mksqlite3c.tcl" "re2-*/re2/re2.cc")
missing=()
for i in "${!packages[@]}"; do
    # shellcheck disable=SC2086 # the pattern is meant to expand
    if ! compgen -G "$deps/${folders[$i]}" >/dev/null; then
        missing+=("${packages[$i]}")
    fi
done
if ((${#missing[@]} > 0)); then
    # shellcheck source=scripts/private-apt.sh
    . "$(dirname "$0")/private-apt.sh"
    private_apt "$deps/apt" deb-src
    echo "windows-deps: fetching the Debian sources of ${missing[*]} into $deps"
    apt-get "${private_apt_options[@]}" -q update
    (cd "$deps" && apt-get "${private_apt_options[@]}" -q source "${missing[@]}")
fi

# SQLite's amalgamation, generated once in a build folder of its own (the unpacked source stays
# as Debian ships it). configure and make run natively: the result is portable C.
amalgamation=$deps/sqlite3-amalgamation
if [[ ! -e "$amalgamation/sqlite3.c" || ! -e "$amalgamation/sqlite3.h" ]]; then
    if ! command -v tclsh >/dev/null; then
        echo "windows-deps: tclsh is missing (scripts/install-deps.sh --windows installs tcl)" >&2
        exit 1
    fi
    sqlite_source=$(compgen -G "$deps/sqlite3-*/tool/mksqlite3c.tcl" | head -n 1)
    sqlite_source=${sqlite_source%/tool/mksqlite3c.tcl}
    echo "windows-deps: generating SQLite's amalgamation from $sqlite_source"
    rm -rf "$amalgamation.build"
    mkdir -p "$amalgamation.build"
    (cd "$amalgamation.build" && "$sqlite_source/configure" --disable-tcl >configure.log 2>&1 &&
        make sqlite3.c >make.log 2>&1) || {
        echo "windows-deps: generating sqlite3.c failed: see $amalgamation.build/*.log" >&2
        exit 1
    }
    mkdir -p "$amalgamation"
    cp "$amalgamation.build/sqlite3.c" "$amalgamation.build/sqlite3.h" "$amalgamation/"
    rm -rf "$amalgamation.build"
fi
# RE2's tables, generated once from its Debian source (the patched unicode.py reads
# /usr/share/unicode, not the network) with its own scripts, as its Makefile's REBUILD_TABLES does.
re2_tables=$deps/re2-tables/re2
if [[ ! -e "$re2_tables/perl_groups.cc" || ! -e "$re2_tables/unicode_casefold.cc" ||
    ! -e "$re2_tables/unicode_groups.cc" ]]; then
    if [[ ! -e /usr/share/unicode/UnicodeData.txt ]]; then
        echo "windows-deps: /usr/share/unicode is missing (scripts/install-deps.sh --windows" \
            "installs unicode-data)" >&2
        exit 1
    fi
    re2_source=$(compgen -G "$deps/re2-*/re2/re2.cc" | head -n 1)
    re2_source=${re2_source%/re2/re2.cc}
    echo "windows-deps: generating RE2's Unicode tables from $re2_source"
    rm -rf "$re2_tables.build"
    mkdir -p "$re2_tables.build"
    (cd "$re2_source" && perl re2/make_perl_groups.pl >"$re2_tables.build/perl_groups.cc" &&
        python3 re2/make_unicode_casefold.py >"$re2_tables.build/unicode_casefold.cc" &&
        python3 re2/make_unicode_groups.py >"$re2_tables.build/unicode_groups.cc") || {
        echo "windows-deps: generating RE2's tables failed" >&2
        exit 1
    }
    rm -rf "$re2_tables"
    mkdir -p "$(dirname "$re2_tables")"
    mv "$re2_tables.build" "$re2_tables"
fi
echo "windows-deps: pugixml, Lua 5.4, cpp-httplib, SQLite, RE2 and the header-only libraries" \
    "are in $deps"
