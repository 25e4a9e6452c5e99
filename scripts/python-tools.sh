#!/usr/bin/env bash
# Installs the third-party JUnit readers the tests run on our reports into the build tree
# (BUILD_DIR/python-tools, a virtual environment of its own): junitparser and xunitparser, from
# PyPI. Versions are pinned; once installed, nothing is fetched again, so the tests run
# offline. Run by ctest as the fixture e2e.python_tools, as scripts/node-tools.sh is; nothing
# is installed outside the build tree.
set -euo pipefail

build=${1:?usage: scripts/python-tools.sh BUILD_DIR [PYTHON]}
python=${2:-python3}
prefix="$build/python-tools"
pins=(junitparser==5.0.3 xunitparser==1.3.4)
stamp="$prefix/installed"

if [[ -f "$stamp" && "$(cat "$stamp")" == "${pins[*]}" ]]; then
    exit 0
fi
rm -rf "$prefix"
if ! "$python" -m venv "$prefix"; then
    echo "python-tools: $python cannot make a virtual environment; run scripts/install-deps.sh" >&2
    exit 1
fi
echo "python-tools: installing ${pins[*]} into $prefix"
"$prefix/bin/python" -m pip install --quiet --disable-pip-version-check --no-input "${pins[@]}"
echo "${pins[*]}" >"$stamp"
