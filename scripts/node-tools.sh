#!/usr/bin/env bash
# Installs the third-party checkers the tests run on our reports into the build tree
# (BUILD_DIR/node-tools): tap-parser (TAP 14, strict), ajv with ajv-formats, and the ctrf package
# for CTRF's published JSON schema. Versions are pinned; once installed, nothing is fetched
# again, so the tests run offline. Run by ctest as the fixture e2e.node_tools (tests/e2e/
# CMakeLists.txt) before the end-to-end tests; configuring the build never calls it.
set -euo pipefail

build=${1:?usage: scripts/node-tools.sh BUILD_DIR}
prefix="$build/node-tools"
pins=(tap-parser@18.3.4 ajv@8.20.0 ajv-formats@3.0.1 ctrf@0.3.0)
stamp="$prefix/installed"

if [[ -f "$stamp" && "$(cat "$stamp")" == "${pins[*]}" ]]; then
    exit 0
fi
if ! command -v npm >/dev/null; then
    echo "node-tools: npm is missing; run scripts/install-deps.sh" >&2
    exit 1
fi
mkdir -p "$prefix"
echo "node-tools: installing ${pins[*]} into $prefix"
npm install --prefix "$prefix" --no-audit --no-fund --loglevel=error "${pins[@]}"
echo "${pins[*]}" >"$stamp"
