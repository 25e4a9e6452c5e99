#!/usr/bin/env bash
# Quick start. Installs the build dependencies (Debian 12), configures and builds in build/,
# then:
#   ./run.sh example    runs the example suites; reports (text, JUnit, TAP, JSON, HTML) in
#                       build/example-reports/
#   ./run.sh test       runs every test (ctest), then the sanitizer job (below); last line
#                       "N passed, N failed" over both
#   ./run.sh sanitize   the sanitizer job alone: builds build-asan/ with -DRTF_SANITIZE=ON
#                       (ASan+UBSan) and runs the unit tests, the isolation and hostile-input
#                       end-to-end tests and the fuzz regression inputs under it
#   ./run.sh coverage   builds build-coverage/ with -DRTF_COVERAGE=ON, runs every test and
#                       writes build-coverage/coverage/index.html and coverage.txt
# The build folder can be moved with RTF_BUILD_DIR (default build).
set -euo pipefail
cd "$(dirname "$0")"
root=$PWD
dir=${RTF_BUILD_DIR:-build}

usage() {
    echo "usage: $0 example|test|sanitize|coverage" >&2
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

# Counts over every run_ctest of this call, for the closing line (see finish).
passed_total=0
failed_total=0

# run_ctest <name> <build dir> [ctest options...]: runs ctest, prints "name: N passed, N failed"
# and adds the counts to the totals. Its log is <build dir>/ctest-<name>.log.
run_ctest() {
    local name=$1 dir=$2
    shift 2
    local log status=0
    log="$dir/ctest-$name.log"
    ctest --test-dir "$dir" -j2 --output-on-failure --timeout 600 "$@" 2>&1 | tee "$log" ||
        status=$?
    local summary passed failed
    summary=$(ctest_summary "$log")
    echo "$name: $summary"
    passed=${summary%% passed*}
    failed=${summary##*, }
    failed=${failed%% failed}
    # A ctest that failed without failing a test (a bad pattern, a crash) still counts as one.
    if [[ $status -ne 0 && $failed -eq 0 ]]; then
        failed=1
    fi
    passed_total=$((passed_total + passed))
    failed_total=$((failed_total + failed))
    [[ $failed -eq 0 ]]
}

# finish: the closing line "N passed, N failed" over every run_ctest; fails if any failed.
finish() {
    echo "${passed_total} passed, ${failed_total} failed"
    [[ $failed_total -eq 0 ]]
}

# The sanitizer job: build-asan/ with address and undefined-behaviour sanitizers; runs
#   - the unit tests and whatever else is neither end-to-end, bench, CTest helpers nor the
#     format check (so the fuzz regression inputs, fuzz.*);
#   - the end-to-end tests of isolation and hostile input: they drive the fork server, workers,
#     pre-started interpreters and the wire format, where memory errors would hide;
# with leak checks on, except for Ruby (below). The options and suppressions come from
# tests/sanitizers/ through ctest (tests/CMakeLists.txt).
sanitizer_job() {
    # Debug: clearer reports. Warnings stay warnings: GCC 12 gives false maybe-uninitialized
    # ones in <regex> with the sanitizers on; the normal build keeps -Werror. The examples are
    # built: test_hostile_runner runs them.
    configure build-asan -DRTF_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
        -DRTF_WARNINGS_AS_ERRORS=OFF -DRTF_BUILD_BENCH=OFF
    # Called as `sanitizer_job || ...`, where set -e does not apply: a failed build counts.
    if ! build build-asan; then
        echo "run.sh: building build-asan failed" >&2
        failed_total=$((failed_total + 1))
        return 1
    fi
    local status=0
    run_ctest asan-unit build-asan -E "^(e2e\.|ctest\.|format$|bench\.)|$sanitized_ruby|$unsanitized" ||
        status=1
    run_ctest asan-e2e build-asan -R "$sanitized_e2e" || status=1
    # LeakSanitizer's exit-time scan crashes on the embedded Ruby VM's thread (GCC 12's
    # LeakSanitizer misreads its dynamic TLS); the Ruby unit tests keep the address and
    # undefined-behaviour checks, without leak checks. The end-to-end tests do the same for a
    # runner that hosts Ruby (tests/e2e/conftest.py).
    ASAN_OPTIONS=detect_leaks=0:handle_segv=0:handle_sigbus=0:handle_sigfpe=0:exitcode=23 \
        run_ctest asan-ruby build-asan -R "$sanitized_ruby" || status=1
    return $status
}

# The coverage job: build-coverage/ with gcov counters (Debug, so lines map to the code), every
# test, then gcovr over src/: an HTML report (coverage/index.html, a page per file), a text one
# (coverage.txt) and the table per folder of src/ (coverage-folders.md, as README.md shows it).
# Branches the compiler adds for exceptions are left out: they are not decisions of ours.
coverage_job() {
    local out=build-coverage
    configure "$out" -DRTF_COVERAGE=ON -DCMAKE_BUILD_TYPE=Debug
    build "$out"
    # Counters add up across runs: start from none.
    find "$out" -name '*.gcda' -delete
    local status=0
    run_ctest coverage "$out" || status=1
    mkdir -p "$out/coverage"
    gcovr --root "$root" --object-directory "$out" --filter "$root/src/" -j 2 \
        --exclude-throw-branches --exclude-unreachable-branches \
        --html-details "$out/coverage/index.html" --txt "$out/coverage.txt" \
        --json-summary "$out/coverage-summary.json" --print-summary
    # The workers' code runs only in children that end with _exit.
    scripts/coverage-folders.py "$out/coverage-summary.json" --ran src/isolation/test_worker.cpp \
        src/isolation/fixture_worker.cpp | tee "$out/coverage-folders.md" || status=1
    echo "Coverage report: $out/coverage/index.html, $out/coverage.txt"
    finish && [[ $status -eq 0 ]]
}

# The end-to-end tests the sanitizer job runs (a ctest -R pattern).
sanitized_e2e='^e2e\.test_(isolation|isolation_interrupts|hostile_exec|hostile_lang|hostile_runner|prestarted_interpreters)$'
# The unit tests that host Ruby in the test program (run without leak checks).
sanitized_ruby='^RubyLoader\.|^Languages/ScriptPluginLoader\..*/rb'
# Timing tests left to the normal build: sanitized (10 to 50 times slower) they measure the
# sanitizers. A parse-time ratio, and a plug-in that must ignore SIGTERM within 0.3 s.
unsanitized='^TapParser\.NestedSubtestsParseInTimeLinearInTheStream$|^Isolation\.TestIgnoringSigtermIsKilledAfterTheGrace$'

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
    run_ctest tests "$dir" || true
    sanitizer_job || true
    finish
    ;;
sanitize)
    scripts/install-deps.sh
    sanitizer_job || true
    finish
    ;;
coverage)
    scripts/install-deps.sh
    coverage_job
    ;;
*)
    usage
    ;;
esac
