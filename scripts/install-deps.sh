#!/usr/bin/env bash
# Installs the Debian packages needed to build and test the project (Debian 12).
# Idempotent and quick when everything is there: apt is only called for what is missing.
#   scripts/install-deps.sh            the Linux build's packages
#   scripts/install-deps.sh --windows  also the Windows job's tools (./run.sh windows):
#                                      MinGW-w64, Wine, dpkg-dev for `apt-get source`,
#                                      tcl to generate SQLite's amalgamation, unicode-data
#                                      and python3-six to generate RE2's tables
#   scripts/install-deps.sh --docs     also the documentation's tools (./run.sh docs and the
#                                      docs.site test of ./run.sh test): mkdocs
#                                      and doxygen
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config
    libgtest-dev libgmock-dev libpugixml-dev libcli11-dev
    libxml2-utils clang-format nlohmann-json3-dev
    python3 python3-dev python3-pytest python3-venv pybind11-dev
    liblua5.4-dev lua5.4 ruby ruby-dev
    mosquitto mosquitto-clients perl nodejs
    libcpp-httplib-dev chromium chromium-driver python3-selenium
    python3-yaml libsqlite3-dev libelf-dev libre2-dev
    gcovr tini ccache
    clang libclang-rt-14-dev
    cyclonedds-dev cyclonedds-tools libddsc0debian
)
# Optional: the Windows job cross-builds with MinGW-w64 (the posix flavour: C++ threads), runs
# under Wine and fetches pugixml's, Lua's and SQLite's sources with `apt-get source`
# (dpkg-source); SQLite's sqlite3.c is generated from its source tree with tclsh (tcl), RE2's
# Unicode tables from unicode-data with its Python scripts (python3-six).
windows_packages=(g++-mingw-w64-x86-64-posix wine64 dpkg-dev tcl unicode-data python3-six)
# Optional: the documentation site (./run.sh docs, scripts/build-docs.sh).
docs_packages=(mkdocs doxygen)
for flag in "$@"; do
    case "$flag" in
    --windows) packages+=("${windows_packages[@]}") ;;
    --docs) packages+=("${docs_packages[@]}") ;;
    *)
        echo "usage: $0 [--windows] [--docs]" >&2
        exit 2
        ;;
    esac
done

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
    if [[ "$status" != "install ok installed" ]]; then
        missing+=("$package")
    fi
done
# npm installs the report checkers into the build tree (scripts/node-tools.sh). Debian's nodejs
# comes without it (the npm package); other nodejs builds (NodeSource) bring their own, which
# Debian's npm package would conflict with.
if ! command -v npm >/dev/null; then
    missing+=(npm)
fi

if ((${#missing[@]} == 0)); then
    echo "install-deps: all ${#packages[@]} packages are installed"
    exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=()
if [[ $(id -u) -ne 0 ]]; then
    sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
