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
prefix="$build/bench-tools"
pins=(pytest==8.3.5 pytest-forked==1.6.0)
stamp="$prefix/installed"

if [[ -f "$stamp" && "$(cat "$stamp")" == "${pins[*]}" ]]; then
    exit 0
fi
rm -rf "$prefix"
if ! "$python" -m venv "$prefix"; then
    echo "bench-tools: $python cannot make a virtual environment; run scripts/install-deps.sh" >&2
    exit 1
fi
echo "bench-tools: installing ${pins[*]} into $prefix"
"$prefix/bin/python" -m pip install --quiet --disable-pip-version-check --no-input "${pins[@]}"
echo "${pins[*]}" >"$stamp"
