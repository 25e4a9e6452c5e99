#!/usr/bin/env bash
# Quick start. Installs the build dependencies (Debian 12), configures and builds in build/,
# then:
#   ./run.sh example    runs the example suites; reports (text, JUnit, TAP, JSON, HTML) in
#                       build/example-reports/
#   ./run.sh test       runs every test (ctest); last line "N passed, N failed"
#   ./run.sh sanitize   builds build-asan/ with -DRTF_SANITIZE=ON and runs the unit tests
# The build folder can be moved with RTF_BUILD_DIR (default build).
set -euo pipefail
cd "$(dirname "$0")"
root=$PWD
dir=${RTF_BUILD_DIR:-build}

usage() {
    echo "usage: $0 example|test|sanitize" >&2
    exit 2
}

# configure <build dir> [cmake options...]: fails on any CMake warning, so none creeps in.
configure() {
    local dir=$1
    shift
    local log
    log=$(mktemp)
    if ! cmake -S "$root" -B "$dir" -G Ninja -Wdev -DRTF_WARNINGS_AS_ERRORS=ON "$@" 2>&1 |
        tee "$log"; then
        rm -f "$log"
        echo "run.sh: configuring $dir failed" >&2
        exit 1
    fi
    if grep -q "CMake Warning" "$log"; then
        rm -f "$log"
        echo "run.sh: CMake printed warnings while configuring $dir (see above)" >&2
        exit 1
    fi
    rm -f "$log"
}

build() {
    cmake --build "$1" -j2
}

# ctest_summary <ctest log>: prints "N passed, N failed" from ctest's own summary line. Tests
# that did not run (skipped, disabled) are neither.
ctest_summary() {
    local line total failed skipped
    line=$(grep -E '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$1" | tail -n 1)
    if [[ -z "$line" ]]; then
        echo "0 passed, 1 failed"
        return
    fi
    failed=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
    total=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\2/' <<<"$line")
    skipped=$(sed -n '/^The following tests did not run:/,/^$/p' "$1" |
        grep -cE '\((Skipped|Disabled)\)$' || true)
    echo "$((total - failed - skipped)) passed, ${failed} failed"
}

run_ctest() {
    local dir=$1
    shift
    local log status=0
    log="$dir/ctest-summary.log"
    ctest --test-dir "$dir" -j2 --output-on-failure --timeout 600 "$@" 2>&1 | tee "$log" ||
        status=$?
    local summary
    summary=$(ctest_summary "$log")
    echo "$summary"
    [[ $status -eq 0 && "$summary" == *" 0 failed" ]]
}

[[ $# -eq 1 ]] || usage
case "$1" in
example)
    scripts/install-deps.sh
    configure "$dir"
    build "$dir"
    build_dir=$(cd "$dir" && pwd)
    examples=$build_dir/examples
    reports=$build_dir/example-reports
    mkdir -p "$reports"
    # Three suites in one run, one report of each type for all: C++ (test and fixture
    # plug-ins), scripts (Python, Lua, Ruby, TAP; a Python fixture) and a robot's world started
    # by the process fixture. From the reports folder, so the world's logs land there too.
    status=0
    (cd "$reports" && "$build_dir/bin/robottestingframework-testrunner" \
        --suite "$examples/example.xml" --suite "$examples/scripts.xml" \
        --suite "$examples/robot/robot.xml" --resources "$examples/robot/ports.json" \
        --output text:example.txt --output junit:example.xml --output tap:example.tap \
        --output json:example.json --output html:example.html) || status=$?
    echo
    echo "Reports in $reports/:"
    echo "  example.txt (text), example.xml (JUnit), example.tap (TAP 14),"
    echo "  example.json (CTRF JSON), example.html (open it in a browser)"
    echo "Logs of the robot's processes: $reports/rtf-logs/robot/"
    exit $status
    ;;
test)
    scripts/install-deps.sh
    configure "$dir"
    build "$dir"
    run_ctest "$dir"
    ;;
sanitize)
    scripts/install-deps.sh
    # Debug: clearer reports. Warnings stay warnings: GCC 12 gives false maybe-uninitialized
    # ones in <regex> with the sanitizers on; the normal build keeps -Werror.
    configure build-asan -DRTF_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
        -DRTF_WARNINGS_AS_ERRORS=OFF -DRTF_BUILD_EXAMPLES=OFF -DRTF_BUILD_BENCH=OFF
    build build-asan
    # The unit tests (GoogleTest), not the end-to-end ones (e2e.*) nor the format check.
    # Signals stay the program's: some tests crash plug-ins on purpose and expect SIGSEGV.
    export ASAN_OPTIONS=detect_leaks=1:handle_segv=0:handle_sigbus=0:handle_sigfpe=0
    export LSAN_OPTIONS=suppressions=$root/scripts/lsan.supp:print_suppressions=0
    export UBSAN_OPTIONS=print_stacktrace=1
    status=0
    run_ctest build-asan -E '^(e2e\.|ctest\.|format$|bench\.|RubyLoader\.)' || status=1
    mv build-asan/ctest-summary.log build-asan/ctest-summary-all.log
    # LeakSanitizer's exit-time scan crashes on the embedded Ruby VM's thread (it cannot stop
    # it); the Ruby tests keep the address and undefined-behaviour checks, without leak checks.
    ASAN_OPTIONS=${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0} run_ctest build-asan -R '^RubyLoader\.' ||
        status=1
    # Undefined behaviour does not stop a test; any outside the crashing test plug-ins fails.
    if cat build-asan/ctest-summary-all.log build-asan/ctest-summary.log | grep -E 'runtime error:' | grep -v '/tests/plugins/'; then
        echo "run.sh: undefined behaviour reported (above)" >&2
        status=1
    fi
    exit $status
    ;;
*)
    usage
    ;;
esac
