#!/usr/bin/env bash
# Fails (and lists the offending places) when a C++ file of ours is not formatted as the
# root .clang-format says. Fix with: clang-format -i <file>
set -euo pipefail
cd "$(dirname "$0")/.."

files=()
while IFS= read -r -d '' file; do
    files+=("$file")
done < <(find include src tests examples bench \( -name '*.cpp' -o -name '*.h' \) -type f \
              -print0 2>/dev/null | sort -z)

if ((${#files[@]} == 0)); then
    echo "check-format: no C++ files found" >&2
    exit 1
fi
clang-format --dry-run --Werror "${files[@]}"
echo "check-format: ${#files[@]} files formatted"
