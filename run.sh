#!/usr/bin/env bash
# Quick start. Installs the build dependencies (Debian 12), configures and builds in build/,
# then:
#   ./run.sh example    runs the example suites; reports (text, JUnit, TAP, JSON, HTML) in
#                       build/example-reports/
#   ./run.sh test       runs every test (ctest), then RTF 2.0.1's own tests against the
#                       installed tree (rtf2_job), the sanitizer job, the portable-POSIX job
#                       and the Windows job (below); last line "N passed, N failed" over all
#   ./run.sh docs       installs mkdocs and doxygen (scripts/install-deps.sh --docs) and builds
#                       the documentation site into build/docs/site/ (scripts/build-docs.sh:
#                       the C++ API reference with Doxygen, warnings as errors; mkdocs
#                       --strict; every internal link checked)
#   ./run.sh rtf2       RTF 2.0.1's own tests alone (scripts/rtf2-tests.sh, build/rtf2/)
#   ./run.sh portable   the portable-POSIX job alone: builds build-portable/ with
#                       -DRTF_PORTABLE_POSIX=ON (the macOS code paths, on Linux) and runs the
#                       unit tests and the isolation, interrupt, fixture and hostile-input
#                       end-to-end tests with it
#   ./run.sh windows    the Windows job alone: installs
#                       MinGW-w64 and Wine if missing (scripts/install-deps.sh --windows),
#                       fetches pugixml's and Lua's Debian sources into build-windows/deps/
#                       (scripts/windows-deps.sh, a private apt configuration), cross-builds
#                       build-windows/ (cmake/mingw-w64.cmake) and runs its tests under Wine
#                       (tests/windows/; Wine's prefix is build-windows/wine/)
#   ./run.sh sanitize   the sanitizer job alone: builds build-asan/ with -DRTF_SANITIZE=ON
#                       (ASan+UBSan) and runs the unit tests, the isolation and hostile-input
#                       end-to-end tests and the fuzz regression inputs under it
#   ./run.sh coverage   builds build-coverage/ with -DRTF_COVERAGE=ON, runs every test and
#                       writes build-coverage/coverage/index.html and coverage.txt
#   ./run.sh bench [OPTIONS...]  every performance figure in one run (bench/perf_bench.py: ours
#                       beside RTF 2.0.1's runner (Debian's packages, unpacked into the build
#                       tree), CTest's, a bare fork's, pytest's and pytest --forked's, measured
#                       in the same run, with ratio and target; about 15 minutes with its soak
#                       run, --soak-count 0 leaves that out, --part NAME picks parts)
#   ./run.sh fuzz [SECONDS [TARGET...]]  builds build-fuzz/ with clang and -DRTF_FUZZ=ON and
#                       runs every fuzz target (or those named) SECONDS (default 60), two at a
#                       time; findings in build-fuzz/findings/<target>/
# The build folder can be moved with RTF_BUILD_DIR (default build).
set -euo pipefail
cd "$(dirname "$0")"
root=$PWD
dir=${RTF_BUILD_DIR:-build}

usage() {
    echo "usage: $0 example|test|docs|rtf2|sanitize|portable|windows|coverage|bench [OPTIONS...]|fuzz [SECONDS [TARGET...]]" >&2
    exit 2
}

# Every build compiles through ccache (scripts/install-deps.sh installs it), one cache for
# all the build folders: the portable-POSIX build differs from the main build only in its
# platform files, so on a fresh machine it compiles those and takes the rest from the main
# build's objects. Paths are taken relative to the repository and the build folder is not
# hashed (an object built with -g names it), or nothing would be shared between folders. The
# cache stays in the build tree (build/ccache) unless the user has one (CCACHE_DIR).
# Set up when first configuring, after install-deps.sh.
launcher=()
ccache_dir=$root/$dir/ccache
use_ccache() {
    if [[ ${#launcher[@]} -eq 0 ]] && command -v ccache >/dev/null; then
        launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
        export CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1
        export CCACHE_DIR=${CCACHE_DIR:-$ccache_dir}
    fi
}

# configure <build dir> [cmake options...]: fails on any CMake warning, so none creeps in.
configure() {
    local dir=$1
    shift
    local log
    use_ccache
    log=$(mktemp)
    if ! cmake -S "$root" -B "$dir" -G Ninja -Wdev -DRTF_WARNINGS_AS_ERRORS=ON "${launcher[@]}" "$@" 2>&1 |
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

# A command run_ctest runs ctest under (the portable job's).
ctest_prefix=()

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
    "${ctest_prefix[@]}" ctest --test-dir "$dir" -j2 --output-on-failure --timeout 600 "$@" 2>&1 | tee "$log" ||
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
    run_ctest asan-unit build-asan -E "^(e2e\.|ctest\.|format$|portable_code$|bench\.)|$sanitized_ruby|$unsanitized" ||
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

# The portable-POSIX job: build-portable/ with -DRTF_PORTABLE_POSIX=ON, the platform code that
# uses only what macOS has (src/platform/*-portable.cpp, src/fixtures/process/*-portable.cpp:
# no prctl, memfd_create, eventfd, pipe2, close_range, SOCK_SEQPACKET, pidfd). Runs the unit
# tests and the end-to-end tests of isolation, interrupts, fixtures and hostile input, so the
# macOS code paths run on every `./run.sh test`. Only the platform files differ from the main
# build, so through ccache (above) the build is mostly cache hits.
portable_job() {
    configure build-portable -DRTF_PORTABLE_POSIX=ON -DRTF_BUILD_BENCH=OFF
    if ! build build-portable; then
        echo "run.sh: building build-portable failed" >&2
        failed_total=$((failed_total + 1))
        return 1
    fi
    local status=0
    run_ctest portable-unit build-portable -E "^(e2e\.|ctest\.|format$|portable_code$|bench\.|fuzz\.)" ||
        status=1
    # Under `tini -s`, a subreaper that reaps the orphans it adopts as launchd does on a Mac:
    # this machine's init leaves them zombies, and the portable build (no subreaper of its own)
    # leaves a test's orphans to it; their zombies would hold each test for the whole grace.
    # Left out: a daemon that leaves its session escapes the portable build, which reaches a
    # test's descendants only through process groups (docs/development/platforms.md).
    ctest_prefix=(tini -s --)
    PYTEST_ADDOPTS="-k 'not test_daemons_of_exec_tests_do_not_survive_the_run'" \
        run_ctest portable-e2e build-portable -R "$portable_e2e" || status=1
    ctest_prefix=()
    return $status
}

# The Windows job: build-windows/ cross-built with MinGW-w64 (cmake/mingw-w64.cmake), its
# dependencies from Debian (scripts/windows-deps.sh), its tests (tests/windows/) run by ctest
# through Wine (the toolchain's CMAKE_CROSSCOMPILING_EMULATOR). Wine keeps its prefix in
# build-windows/wine/ (made on the first start, about 10 s) and one wineserver for the whole
# job, so each test's start is quick; the server is stopped at the end.
windows_job() {
    local out=build-windows
    if ! scripts/windows-deps.sh "$out"; then
        echo "run.sh: fetching the Windows build's dependencies failed" >&2
        failed_total=$((failed_total + 1))
        return 1
    fi
    configure "$out" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/mingw-w64.cmake" \
        -DRTF_BUILD_BENCH=OFF -DRTF_BUILD_EXAMPLES=OFF
    if ! build "$out"; then
        echo "run.sh: building $out failed" >&2
        failed_total=$((failed_total + 1))
        return 1
    fi
    export WINEPREFIX=$root/$out/wine WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
    mkdir -p "$WINEPREFIX"
    # One wineserver for the whole job, started with -p before any Wine program: -p only
    # applies to a server it starts, and the one a program starts (Debian's -p0) exits with its
    # last program, failing one starting at that moment ("wine client error:0: recvmsg:
    # Connection reset by peer"). A server left by an earlier job is ended first.
    /usr/lib/wine/wineserver -k 2>/dev/null || true
    /usr/lib/wine/wineserver -w
    /usr/lib/wine/wineserver -p
    timeout 300 /usr/lib/wine/wine64 wineboot --init
    local status=0
    run_ctest windows "$out" || status=1
    # Ended by the tests' last (windows.wineserver_stop); again here whatever the tests did.
    /usr/lib/wine/wineserver -k 2>/dev/null || true
    /usr/lib/wine/wineserver -w
    return $status
}

# The RTF 2.x job: RTF 2.0.1's own tests/ tree, from Debian 12's source package, built unchanged
# with its own CMake helpers against this build installed (scripts/rtf2-tests.sh, everything in
# <build dir>/rtf2/), then its ctest: every test but misc::check_license (which checks the
# licence headers of RTF's own sources) counts in the closing line.
rtf2_job() {
    if ! scripts/rtf2-tests.sh "$dir"; then
        echo "run.sh: building RTF 2.0.1's tests failed" >&2
        failed_total=$((failed_total + 1))
        return 1
    fi
    # One at a time, as RTF 2.x ran them: its add_suite test's cleanup (FIXTURES_CLEANUP of a
    # fixture no test requires) would otherwise remove the demo's folder while it is built.
    run_ctest rtf2 "$dir/rtf2/build" -j1 -E '^misc::check_license$'
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
    # libgcov's own complaints (a .gcda another process left half written) go to a file, not
    # into the output of the test whose process wrote them, where reports would show them.
    export GCOV_ERROR_FILE=$root/$out/gcov-errors.log
    rm -f "$GCOV_ERROR_FILE"
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
    if [[ -s "$GCOV_ERROR_FILE" ]]; then
        echo "coverage: libgcov reported problems (the files it names may count low):"
        sort -u "$GCOV_ERROR_FILE" | head -n 20
    fi
    echo "Coverage report: $out/coverage/index.html, $out/coverage.txt"
    finish && [[ $status -eq 0 ]]
}

# The end-to-end tests the sanitizer job runs (a ctest -R pattern).
sanitized_e2e='^e2e\.test_(isolation|isolation_interrupts|hostile_exec|hostile_lang|hostile_runner|prestarted_interpreters)$'
# The end-to-end tests the portable-POSIX job runs (a ctest -R pattern).
portable_e2e='^e2e\.test_(isolation|isolation_interrupts|fixture_process|runner_fixtures|hostile_[a-z_]+)$'
# The unit tests that host Ruby in the test program (run without leak checks).
sanitized_ruby='^RubyLoader\.|^Languages/ScriptPluginLoader\..*/rb'
# Timing tests left to the normal build: sanitized (10 to 50 times slower) they measure the
# sanitizers. A parse-time ratio, and a plug-in that must ignore SIGTERM within 0.3 s.
unsanitized='^TapParser\.NestedSubtestsParseInTimeLinearInTheStream$|^Isolation\.TestIgnoringSigtermIsKilledAfterTheGrace$'


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

[[ $# -eq 1 || "$1" == fuzz || "$1" == bench ]] || usage
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
    scripts/install-deps.sh --windows --docs
    configure "$dir"
    build "$dir"
    run_ctest tests "$dir" || true
    rtf2_job || true
    sanitizer_job || true
    portable_job || true
    windows_job || true
    finish
    ;;
docs)
    scripts/install-deps.sh --docs
    exec scripts/build-docs.sh "$dir"
    ;;
rtf2)
    scripts/install-deps.sh
    configure "$dir"
    build "$dir"
    rtf2_job || true
    finish
    ;;
sanitize)
    scripts/install-deps.sh
    sanitizer_job || true
    finish
    ;;
portable)
    scripts/install-deps.sh
    portable_job || true
    finish
    ;;
windows)
    scripts/install-deps.sh --windows
    windows_job || true
    finish
    ;;
coverage)
    scripts/install-deps.sh
    coverage_job
    ;;
bench)
    shift
    scripts/install-deps.sh
    configure "$dir"
    build "$dir"
    exec python3 bench/perf_bench.py --build "$dir" "$@"
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
