#!/usr/bin/env bash
# The portable files compile without GCC-only things (docs/development/platforms.md). The library users
# link (include/, src/core, src/reporters, src/dll, src/variables) is what a Windows build takes
# first; a file named for its platform or compiler (-posix, -linux, -portable, -windows, -apple,
# -itanium, -msvc) and the fuzz targets (clang only) are left out. Two checks:
#   1. no GCC-only header (cxxabi.h, <bits/...>, <ext/...>), __builtin_*, __PRETTY_FUNCTION__,
#      and no __attribute__ except in a #define or under #if defined(__GNUC__);
#   2. clang++ -Wpedantic -Werror -fsyntax-only on the same .cpp files with their flags from
#      <build dir>/compile_commands.json: GNU extensions (variable-length arrays, statement
#      expressions, zero-size arrays, ...) are errors.
# MSVC itself is not run here (there is none on these machines).
# Usage: scripts/check-portable-code.sh [BUILD_DIR]  (default build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
status=0

files=$(find include src/core src/reporters src/dll src/variables -type f \
    \( -name '*.cpp' -o -name '*.h' \) |
    grep -vE -- '-(posix|linux|portable|apple|itanium|msvc|windows)\.cpp$|_fuzz\.cpp$' | sort)

# 1. What only GCC (and Clang pretending to be GCC) has.
if grep -nE '#[[:space:]]*include[[:space:]]*<(cxxabi\.h|bits/|ext/)|__builtin_|__PRETTY_FUNCTION__' \
    $files; then
    echo "check-portable-code: GCC-only header or built-in above (move it to a file named for" \
        "its compiler or platform)" >&2
    status=1
fi
for file in $files; do
    # An __attribute__ is fine in a #define (the macro has another definition elsewhere) or
    # between #if defined(__GNUC__) and its #endif.
    awk -v file="$file" '
        /^[[:space:]]*#[[:space:]]*if/ { depth++; gnu[depth] = ($0 ~ /__GNUC__|__clang__/) }
        /^[[:space:]]*#[[:space:]]*endif/ { gnu[depth] = 0; depth-- }
        /__attribute__/ && !/^[[:space:]]*#[[:space:]]*define/ {
            guarded = 0
            for (i = 1; i <= depth; i++) if (gnu[i]) guarded = 1
            if (!guarded) { printf "%s:%d: %s\n", file, NR, $0; bad = 1 }
        }
        END { exit bad }' "$file" || {
        echo "check-portable-code: __attribute__ without a macro or #if defined(__GNUC__)" >&2
        status=1
    }
done

# 2. GNU extensions, as clang sees them with -Wpedantic.
if [[ ! -f "$build/compile_commands.json" ]]; then
    echo "check-portable-code: no $build/compile_commands.json (configure $build first)" >&2
    exit 1
fi
python3 - "$build/compile_commands.json" $files <<'PY' || status=1
import json, os, shlex, subprocess, sys
from concurrent.futures import ThreadPoolExecutor

commands = json.load(open(sys.argv[1]))
wanted = {os.path.abspath(f) for f in sys.argv[2:] if f.endswith(".cpp")}
jobs = {}
for entry in commands:
    source = os.path.abspath(os.path.join(entry["directory"], entry["file"]))
    if source not in wanted or source in jobs:
        continue
    words = shlex.split(entry["command"]) if "command" in entry else entry["arguments"]
    flags = []
    for i, w in enumerate(words):
        if w in ("-isystem", "-I", "-D") and i + 1 < len(words):
            flags += [w, words[i + 1]]  # the folder or definition is the next word
        elif w.startswith(("-I", "-D", "-isystem")) and w != "-isystem":
            flags.append(w)
    jobs[source] = (entry["directory"],
                    ["clang++", "-std=c++17", "-fsyntax-only", "-Wpedantic", "-Werror"] + flags
                    + [source])

def run(item):
    source, (folder, command) = item
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True)
    return source, done.returncode, done.stderr

failed = 0
with ThreadPoolExecutor(2) as pool:
    for source, code, errors in pool.map(run, sorted(jobs.items())):
        if code != 0:
            failed += 1
            sys.stderr.write(errors)
missing = sorted(wanted - set(jobs))
print(f"check-portable-code: {len(jobs)} files compiled with clang -Wpedantic, {failed} failed"
      + (f"; not in the build: {len(missing)}" if missing else ""))
sys.exit(1 if failed else 0)
PY
exit $status
