#!/usr/bin/env bash
# Installs the bench's own peer, pytest-forked (pytest's plug-in that runs each test in a
# forked process, as this runner isolates each test), from PyPI into the build tree
# (BUILD_DIR/bench-tools, a virtual environment of its own). Versions are pinned, pytest with
# it: pytest-forked (1.6.0 and 1.7.5) cannot send pytest 9's reports back from its forked
# child (`NodeId` is not marshallable: every test fails), so the venv has the last pytest 8.
# Once installed, nothing is fetched again. Run by bench/perf_bench.py (`./run.sh bench`) when
# it is missing, as scripts/python-tools.sh is by the tests; nothing is installed outside the
# build tree.
set -euo pipefail

build=${1:?usage: scripts/bench-tools.sh BUILD_DIR [PYTHON]}
python=${2:-python3}
# shellcheck source=scripts/pinned-venv.sh
. "$(dirname "$0")/pinned-venv.sh"
pinned_venv bench-tools "$build/bench-tools" "$python" pytest==8.3.5 pytest-forked==1.6.0
