#!/usr/bin/env bash
# Quick start. Installs the build dependencies (Debian 12), configures and builds in build/,
# then:
#   ./run.sh example    runs the example suites; reports (text, JUnit, TAP, JSON, HTML) in
#                       build/example-reports/
#   ./run.sh test       runs every test (ctest); last line "N passed, N failed"
#   ./run.sh sanitize   builds build-asan/ with -DRTF_SANITIZE=ON and runs the unit tests
#   ./run.sh fuzz [SECONDS [TARGET...]]  builds build-fuzz/ with clang and -DRTF_FUZZ=ON and
#                       runs every fuzz target (or those named) SECONDS (default 60), two at a
#                       time; findings in build-fuzz/findings/<target>/
# The build folder can be moved with RTF_BUILD_DIR (default build).
set -euo pipefail
cd "$(dirname "$0")"
root=$PWD
dir=${RTF_BUILD_DIR:-build}

usage() {
    echo "usage: $0 example|test|sanitize|fuzz [SECONDS [TARGET...]]" >&2
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

# fuzz_target <build dir> <target> <seconds>: runs one libFuzzer program of <build dir>/bin for
# <seconds> in all; its log is <build dir>/logs/<target>.log, what it found goes to
# <build dir>/findings/<target>/. Prints one line: the target, its executions and its result.
# libFuzzer's -timeout is wall-clock time, so a busy machine can stop it on an input that is
# not slow: an input that timed out is run again alone, and only one that times out again is a
# finding. Otherwise it is set aside (findings/<target>/unconfirmed/) and fuzzing goes on, from
# the corpus kept in <build dir>/corpus/<target>/, for the rest of the time.
fuzz_target() {
    local dir=$1 target=$2 seconds=$3
    local log=$dir/logs/$target.log findings=$dir/findings/$target/
    local options=(-timeout=1 -rss_limit_mb=2048 -print_final_stats=1
        -artifact_prefix="$findings")
    mkdir -p "$findings/unconfirmed" "$dir/corpus/$target" "$dir/logs"
    : >"$log"
    if [[ -f tests/fuzz-corpus/$target.dict ]]; then
        options+=(-dict="tests/fuzz-corpus/$target.dict")
    fi
    local end=$((SECONDS + seconds)) runs=0 status=0 slow=0 left artifact
    while ((status == 0 && (left = end - SECONDS) > 0)); do
        touch "$dir/logs/$target.start"
        # New inputs go to the first folder (build tree); the seeds stay as they are.
        nice -n 19 "$dir/bin/fuzz-$target" "${options[@]}" -max_total_time="$left" \
            "$dir/corpus/$target" "tests/fuzz-corpus/$target" >>"$log" 2>&1 || status=$?
        local executed
        executed=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
        runs=$((runs + ${executed:-0}))
        sed -i 's/^stat::number_of_executed_units:/counted &/' "$log"
        artifact=$(find "$findings" -maxdepth 1 -type f -newer "$dir/logs/$target.start" |
            head -n 1)
        if [[ $status -eq 70 && "$artifact" == */timeout-* ]] &&
            "$dir/bin/fuzz-$target" -timeout=1 "$artifact" >>"$log" 2>&1; then
            echo "run.sh: $artifact did not time out when run alone: machine load" >>"$log"
            mv "$artifact" "$findings/unconfirmed/"
            slow=$((slow + 1))
            status=0
        fi
    done
    rm -f "$dir/logs/$target.start"
    local note=""
    if ((slow > 0)); then
        note=" ($slow timeouts not reproduced alone, set aside)"
    fi
    if [[ $status -eq 0 ]]; then
        echo "fuzz $target: $runs executions in $seconds s, no finding$note"
    else
        echo "fuzz $target: $runs executions, FINDING (exit $status): $(
            grep -E 'ERROR: |runtime error:' "$log" | tail -n 1)$note"
        echo "  log: $log; input: ${artifact:-none}"
    fi
    return $status
}

[[ $# -eq 1 || "$1" == fuzz ]] || usage
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
        --suite "$examples/robot/robot.xml" \
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
fuzz)
    seconds=${2:-60}
    [[ "$seconds" =~ ^[1-9][0-9]*$ ]] || usage
    scripts/install-deps.sh
    # Only what the fuzz targets need: no tests, examples, benchmarks nor embedded languages.
    configure build-fuzz -DRTF_FUZZ=ON -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
        -DRTF_BUILD_TESTS=OFF -DRTF_BUILD_EXAMPLES=OFF -DRTF_BUILD_BENCH=OFF \
        -DRTF_ENABLE_PYTHON=OFF -DRTF_ENABLE_LUA=OFF -DRTF_ENABLE_RUBY=OFF
    cmake --build build-fuzz -j2 --target fuzz
    targets=$(cd build-fuzz/bin && ls fuzz-* | sed 's/^fuzz-//')
    if [[ $# -gt 2 ]]; then
        for target in "${@:3}"; do
            grep -qx "$target" <<<"$targets" || {
                echo "run.sh: no fuzz target '$target' (there are: $(echo $targets))" >&2
                exit 2
            }
        done
        targets="${*:3}"
    fi
    # Each run's findings are its own; the corpus (build-fuzz/corpus/) keeps growing.
    rm -rf build-fuzz/findings
    # Leaks are findings; undefined behaviour halts (-fno-sanitize-recover=all) with a trace.
    export ASAN_OPTIONS=detect_leaks=1
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    export -f fuzz_target
    status=0
    # Two at a time; each prints its line when it ends.
    printf '%s\n' $targets | xargs -P 2 -I{} bash -c 'fuzz_target build-fuzz "$1" "$2"' _ {} \
        "$seconds" | tee build-fuzz/fuzz-summary.log || status=$?
    count=$(wc -w <<<"$targets")
    found=$(grep -c 'FINDING' build-fuzz/fuzz-summary.log || true)
    runs=$(sed -nE 's/^fuzz [^:]+: ([0-9]+) executions.*/\1/p' build-fuzz/fuzz-summary.log |
        awk '{ total += $1 } END { print total + 0 }')
    echo "fuzz: $count targets, ${runs:-0} executions, $found with findings (build-fuzz/findings/)"
    [[ $status -eq 0 && $found -eq 0 ]]
    ;;
*)
    usage
    ;;
esac
