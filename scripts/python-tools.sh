#!/usr/bin/env bash
# Installs the third-party JUnit readers the tests run on our reports into the build tree
# (BUILD_DIR/python-tools, a virtual environment of its own): junitparser and xunitparser, from
# PyPI. Versions are pinned; once installed, nothing is fetched again, so the tests run
# offline. Run by ctest as the fixture e2e.python_tools, as scripts/node-tools.sh is; nothing
# is installed outside the build tree.
set -euo pipefail

build=${1:?usage: scripts/python-tools.sh BUILD_DIR [PYTHON]}
python=${2:-python3}
# shellcheck source=scripts/pinned-venv.sh
. "$(dirname "$0")/pinned-venv.sh"
pinned_venv python-tools "$build/python-tools" "$python" junitparser==5.0.3 xunitparser==1.3.4
