#!/usr/bin/env bash
# rtf2-binaries.sh BUILD_DIR: Debian 12's binary packages of RTF 2.0.1 (its libraries, headers,
# its runner and their TinyXML and Lua), downloaded once through a private apt configuration and unpacked with
# `dpkg -x` into BUILD_DIR/rtf2-binary/root/, never installed into the system. The tests build
# plug-ins against them, as a user of Debian's or conda-forge's RTF 2.0.1 did, and run them with
# this project's runner (tests/e2e/test_rtf2_built_plugins.py); the bench (bench/perf_bench.py)
# runs RTF 2.0.1's own runner beside ours, with LD_LIBRARY_PATH into that tree.
set -euo pipefail
[[ $# -eq 1 ]] || {
    echo "usage: $0 BUILD_DIR" >&2
    exit 2
}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$1/rtf2-binary"
out=$(cd "$1/rtf2-binary" && pwd)
if compgen -G "$out/root/usr/include/*/robottestingframework/TestCase.h" >/dev/null &&
    [[ -x "$out/root/usr/bin/robottestingframework-testrunner" ]]; then
    exit 0
fi
# shellcheck source=scripts/private-apt.sh
. "$root/scripts/private-apt.sh"
private_apt "$out/apt" deb
apt-get "${private_apt_options[@]}" -q update
packages=(librobottestingframework2 librobottestingframework-dll2 librobottestingframework-dev
    librobottestingframework-lua2 librobottestingframework-ruby2 robottestingframework-testrunner
    libtinyxml2.6.2v5 liblua5.3-0)
rm -rf "$out/debs" "$out/root"
mkdir -p "$out/debs"
(cd "$out/debs" && apt-get "${private_apt_options[@]}" -q download "${packages[@]}")
for deb in "$out"/debs/*.deb; do
    dpkg -x "$deb" "$out/root"
done
echo "rtf2-binaries: RTF 2.0.1's libraries and headers are in $out/root"
