#!/usr/bin/env bash
# rtf2-tests.sh BUILD_DIR: prepares RTF 2.0.1's own tests to run against this project's
# installed tree, in BUILD_DIR/rtf2/:
#   source/     tests/, cmake/ and examples/ of RTF 2.0.1, from Debian 12's source package
#               (its orig tarball, fetched once through a private apt configuration, apt/;
#               Debian's own part of that package is not needed and not always served);
#               RTF 2.x's implementation (src/) is not unpacked
#   installed/  BUILD_DIR installed (`cmake --install`), as users install it
#   build/      tests/rtf2/CMakeLists.txt configured and built there: RTF 2.0.1's tests/ built
#               unchanged with its own CMake helpers
# Then `ctest --test-dir BUILD_DIR/rtf2/build -E '^misc::check_license$'` runs them (run.sh
# test does; misc::check_license checks the licence headers of RTF's own sources).
set -euo pipefail
[[ $# -eq 1 ]] || {
    echo "usage: $0 BUILD_DIR" >&2
    exit 2
}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$1/rtf2"
out=$(cd "$1/rtf2" && pwd)
build_dir=$(cd "$1" && pwd)

source=$out/source
if [[ ! -e $source/tests/CMakeLists.txt ]]; then
    # shellcheck source=scripts/private-apt.sh
    . "$root/scripts/private-apt.sh"
    private_apt "$out/apt" deb-src
    echo "rtf2-tests: fetching RTF 2.0.1's Debian source package into $out"
    apt-get "${private_apt_options[@]}" -q update
    # --download-only: the orig tarball is all that is needed; a missing Debian part (answered
    # 404 at times) must not stop it.
    (cd "$out" && apt-get "${private_apt_options[@]}" -q --download-only source \
        robot-testing-framework) || true
    tarball=$(compgen -G "$out/robot-testing-framework_2.0.1*.orig.tar.*" | head -n 1) || true
    if [[ -z $tarball ]]; then
        echo "rtf2-tests: Debian's source package robot-testing-framework (2.0.1) could not" \
            "be fetched (see above)" >&2
        exit 1
    fi
    rm -rf "$source"
    mkdir -p "$source"
    tar -xf "$tarball" -C "$source" --strip-components=1 --wildcards \
        '*/tests/*' '*/cmake/*' '*/examples/*'
fi

cmake --install "$build_dir" --prefix "$out/installed" >/dev/null
cmake -S "$root/tests/rtf2" -B "$out/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DRTF2_SOURCE_DIR="$source" -DCMAKE_PREFIX_PATH="$out/installed" >"$out/configure.log" 2>&1 || {
    cat "$out/configure.log" >&2
    echo "rtf2-tests: configuring RTF 2.0.1's tests failed" >&2
    exit 1
}
cmake --build "$out/build" -j2
