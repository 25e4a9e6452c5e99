#include "runner/cli/option_table.h"

#include "reporters/reporter_registry.h"
#include "runner/model/value_limits.h"

#include <CLI/CLI.hpp>

#include <algorithm>

namespace robottestingframework {
namespace runner {

namespace {

using Takes = OptionRow::Takes;

// A number check by the rule suite files follow too (value_limits.h); its message says what is
// expected, where CLI11's own would print the type's range.
template <typename Number>
ValueRule numberRule(std::string (*check)(const std::string&, Number&), std::string expected) {
    return ValueRule{[check](std::string& text) -> std::string {
                         Number value{};
                         const std::string problem = check(text, value);
                         return problem.empty() ? problem : "'" + text + "' " + problem;
                     },
                     std::move(expected)};
}

// A CLI11 validator as a rule of the table, with its description ({none,process}).
ValueRule cliRule(const CLI::Validator& validator) {
    return ValueRule{[validator](std::string& text) { return validator(text); },
                     validator.get_description()};
}

const std::string seconds = std::to_string(static_cast<long>(maxTimeoutSeconds));

}  // namespace

const char* const programSummary = "Runs Robot Testing Framework test cases and suites.";
const char* const exitStatusHelp =
    "Exit status: 0 when every test passed (skipped ones allowed), 1 when a test failed, "
    "errored, crashed, timed out or could not be loaded, or a fixture failed, 2 on a usage or "
    "configuration error (bad option, unreadable or malformed suite file, unknown dependency, "
    "an output that could not be written), 5 when no test is selected (unless --allow-empty), "
    "130 when interrupted by Ctrl-C (SIGINT), 143 when stopped by SIGTERM.";

std::string OptionRow::longName() const {
    const std::vector<std::string> names = spelledNames();
    for (const std::string& name : names) {
        if (name.rfind("--", 0) == 0) {
            return name;
        }
    }
    return names.empty() ? std::string() : names.front();
}

std::vector<std::string> OptionRow::spelledNames() const {
    std::vector<std::string> spelled;
    if (takes == Takes::Arguments) {
        return spelled;
    }
    std::size_t start = 0;
    while (start <= names.size()) {
        const std::size_t comma = std::min(names.find(',', start), names.size());
        spelled.push_back(names.substr(start, comma - start));
        start = comma + 1;
    }
    return spelled;
}

std::vector<OptionRow> optionTable(Options& o, CommandLineWords& w) {
    const char* const inputs = "Tests to run";
    const char* const selection = "Selection";
    const char* const running = "Running";
    const char* const console = "Console and outputs";
    const char* const web = "Live web page";
    const char* const shards = "Shards, merging and history";
    const char* const help = "Help";
    // clang-format off
    std::vector<OptionRow> rows{
        {"-h,-?,--help", "", Takes::Help, help, "Print this help message and exit", {}, {}, true},
        {"--version", "", Takes::Nothing, help, "Print the version and exit", &w.version, {}, true},
        {"--help-man", "", Takes::Nothing, "", "Print the man page (roff) and exit", &w.helpMan},
        {"--help-markdown", "", Takes::Nothing, "",
         "Print the command-line reference (Markdown) and exit", &w.helpMarkdown},

        {"-t,--test", "FILE", Takes::Repeatable, inputs, "Run the test case in FILE (repeatable)",
         &o.tests, {}, true},
        {"--tests", "DIR", Takes::Repeatable, inputs, "Run every test case in the folder DIR",
         &o.testDirs, {}, true},
        {"-s,--suite", "FILE", Takes::Repeatable, inputs,
         "Run the suite in the XML FILE (repeatable)", &o.suites, {}, true},
        {"--suites", "DIR", Takes::Repeatable, inputs,
         "Run every suite (*.xml) in the folder DIR; world files and JUnit reports there are "
         "passed over",
         &o.suiteDirs, {}, true},
        {"-r,--recursive", "", Takes::Nothing, inputs,
         "--tests and --suites look in sub-folders too", &o.recursive, {}, true},
        {"-p,--param", "TEXT", Takes::One, inputs,
         "Param for the tests that have none of their own", &o.param, {}, true, true},
        {"-e,--environment", "TEXT", Takes::One, inputs,
         "Environment for every test, after the suite's own", &o.environment, {}, true,
         true},
        {"--repetition", "N", Takes::One, inputs,
         "Run each test N times (a test's own repetition wins)", &o.repetition,
         numberRule(checkRunnerRepetition,
                    "from 1 to " + std::to_string(maxRepetition) + "; 0, RTF 2.x's default: once"),
         true},
        {"--var", "NAME=VALUE", Takes::Repeatable, inputs,
         "Set the variable NAME, used as ${NAME} in suites, test files and world files; wins "
         "over --var-file and the files' own (repeatable)", &w.variables},
        {"--var-file", "FILE", Takes::Repeatable, inputs,
         "Read variables from FILE, NAME=VALUE per line, # comments; a later file wins "
         "(repeatable)", &o.variableFiles},
        {"--plugin-path", "DIR", Takes::Repeatable, inputs,
         "Look plug-ins named without a folder up in DIR too: after the suite's folder, before "
         "RTF_PLUGIN_PATH and the system's library path (repeatable, in order)", &o.pluginPath},

        {"--tag", "EXPR", Takes::Repeatable, selection,
         "Run only the tests whose tags match EXPR: a tag or pattern (*, ?), with AND, OR, NOT "
         "(e.g. armANDslow, 'arm OR leg', 'NOT slow'); repeatable, any may match", &w.tags},
        {"--exclude-tag", "EXPR", Takes::Repeatable, selection,
         "Leave out the tests whose tags match EXPR (repeatable)", &w.excludedTags},
        {"--filter", "PATTERN", Takes::Repeatable, selection,
         "Run only the tests whose id (suite/test, as --list shows it) matches: patterns with * "
         "and ?, separated by ':', negative ones after '-' (e.g. 'arm/*-*slow*'); '\\' makes "
         "the next character literal ('arm/*\\-fast'); a test's id written as it is selects "
         "that test alone", &w.filters},
        {"-k,--keyword", "EXPR", Takes::One, selection,
         "Run only the tests matching EXPR, as pytest's -k: names matched without case as "
         "substrings of the test's id (suite/test) or of a tag, with and, or, not and "
         "parentheses (e.g. -k 'speed and not slow'); with --filter and --tag, a test must "
         "match all", &w.keyword},
        {"--rerun-failed", "REPORT", Takes::One, selection,
         "Run only the tests that failed, errored, crashed or timed out in REPORT, a JUnit or "
         "JSON output of an earlier run, or in the last run of a --history file",
         &o.rerunFailed},
        {"--lf,--last-failed", "", Takes::Nothing, selection,
         "Run only the tests that failed, errored, crashed or timed out in the last run, as the "
         "cache folder keeps them (--cache-dir); when none did, or none of them is selected, "
         "every test runs, with a note", &o.lastFailed},
        {"--ff,--failed-first", "", Takes::Nothing, selection,
         "Run the last run's failures first (their suites first, and those tests first in "
         "each), then the rest", &o.failedFirst},
        {"--cache-dir", "DIR", Takes::One, selection,
         "The cache folder that keeps the last run's failures for --lf and --ff (default "
         ".rtf_cache in the working folder); written after a run that has a failure or when it "
         "exists, never by --list", &o.cacheDir},
        {"--no-cache", "", Takes::Nothing, selection,
         "Neither read nor write the cache folder (as pytest's -p no:cacheprovider)",
         &o.noCache},
        {"--allow-empty", "", Takes::Nothing, selection,
         "A run with no test selected (by --filter, --tag, --rerun-failed, or suites without "
         "tests) exits 0 instead of 5", &o.allowEmpty},
        {"--list", "", Takes::Nothing, selection,
         "Print what would run (suite, test, type, plug-in, param, tags, timeout) and exit "
         "without loading or starting anything; --output json:FILE writes it as JSON", &o.list},
        {"--list-vars", "", Takes::Nothing, selection,
         "Print each suite's variables, their values and where they come from, and exit",
         &o.listVariables},

        {"--isolation", "MODE", Takes::One, running,
         "Where tests run: process (each in a worker process; the default) or none (in the "
         "runner's process)", &w.isolation, cliRule(CLI::IsMember({"none", "process"}))},
        {"--network", "NETWORK", Takes::One, running,
         "private: every suite runs in a network of its own, loopback only, so suites side by "
         "side bind the same fixed ports (Linux); host: the machine's network, unless a suite "
         "says network=\"private\" (the default)", &w.network,
         cliRule(CLI::IsMember({"private", "host"}))},
        {"-j,--jobs", "N", Takes::One, running,
         "Run up to N suites at once, each with its own fixtures; 'auto': one per core "
         "(default 1)", &w.jobs},
        {"--resources", "FILE", Takes::One, running,
         "The pools <resource pool=\"...\"/> takes items from: a JSON file shaped like CTest's "
         "resource spec file", &o.resources},
        {"--timeout", "SECONDS", Takes::One, running,
         "Time limit of each test, set-up and tear-down included; a suite's <timeout> and a "
         "test's timeout=\"...\" win (default: none)", &o.timeout, numberRule(checkSeconds, "from 0 (no limit) to " + seconds)},
        {"--watch", "", Takes::Nothing, running,
         "Run again whenever a suite file, a test file or a plug-in changes, the tests that "
         "failed first; Ctrl-C stops (inotify on Linux, polling elsewhere, not on Windows)",
         &o.watch},
        {"--fail-fast", "", Takes::Nothing, running,
         "Stop the run at the first failure; the remaining tests are skipped", &o.failFast},
        {"--retries", "N", Takes::One, running,
         "Run a failing test again up to N times; one that passes on a later attempt is flaky "
         "(default 0)", &o.retries, numberRule(checkRetries, "from 0 to " + std::to_string(maxRetries))},
        {"--fail-on-flaky", "", Takes::Nothing, running,
         "A flaky test fails the run (exit status 1)", &o.failOnFlaky},
        {"--repeat-until-fail", "N", Takes::One, running,
         "Run the selection up to N times, stopping after the first run that fails",
         &o.repeatUntilFail, numberRule(checkRepetition, "from 1 to " + std::to_string(maxRepetition))},
        {"--world-up", "DIR", Takes::One, running,
         "Set up the suite's fixtures (its world, and its private network) in a keeper process "
         "that outlives this one, with its control socket in DIR; exit 0 when the world is up, "
         "1 with the reason when it failed. The keeper stops its world when the process that "
         "started the runner (ctest) ends (docs/how-to/ctest-worlds.md)", &o.worldUp},
        {"--world", "DIR", Takes::One, running,
         "Run the suite's tests in the world a --world-up DIR keeper holds, without setting up "
         "the suite's fixtures; exit 2 when no keeper is there", &o.world},
        {"--world-down", "DIR", Takes::One, running,
         "Stop the world the --world-up DIR keeper holds and print its tear-down; exit 1 when "
         "the tear-down failed", &o.worldDown},
        {"--shared-worlds", "DIR", Takes::One, running,
         "With --world-up: the suite's shared worlds (scope=\"run\") are the ones the "
         "--world-up DIR keeper of those worlds holds, not started again; the suite's world "
         "joins that keeper's network (docs/how-to/ctest-worlds.md)", &o.sharedWorlds},

        {"-o,--output", "FILE", Takes::Repeatable, console,
         "Write the results to FILE, or TYPE:FILE (e.g. junit:results.xml; - or /dev/stdout: "
         "the standard output, the console then going to stderr); repeatable. Default: "
         "result.txt", &w.outputs, {}, true},
        {"--output-type", "TYPE", Takes::One, console,
         "Type of the --output files without a TYPE: " + reporters::reporterTypeList() +
             " (default text)", &w.outputType, {}, true},
        {"--no-output", "", Takes::Nothing, console, "Write no result file", &o.noOutput, {},
         true},
        {"--no-summary", "", Takes::Nothing, console,
         "Leave the summary out of the console and the text output", &o.noSummary, {}, true},
        {"-d,--detail", "", Takes::Nothing, console, "Show every check on the console", &o.detail,
         {}, true},
        {"-v,--verbose", "", Takes::Nothing, console,
         "Show the tests' reports and what they print on the console", &o.verbose, {}, true},
        {"--color", "WHEN", Takes::One, console,
         "Colour on the console: auto (on a terminal, unless NO_COLOR is set), always, never "
         "(default auto)", &w.colour},

        {"-w,--web-reporter", "", Takes::Nothing, web, "Show the run live in a web page",
         &o.webReporter, {}, true},
        {"--web-port", "N", Takes::One, web,
         "Port of the web reporter (default 8080; 0 picks a free one)", &o.webPort,
         cliRule(CLI::Range(0, 65535)), true},
        {"--web-host", "ADDRESS", Takes::One, web,
         "Address the web reporter listens on (default 127.0.0.1, this machine only)",
         &o.webHost},
        {"--web-linger", "SECONDS", Takes::One, web,
         "Keep serving the final web page this long after the run (default 0: exit when the run "
         "ends)", &o.webLinger, numberRule(checkSeconds, "from 0 to " + seconds)},

        {"--shard-index", "I", Takes::One, shards,
         "Run only shard I (from 0) of the selected suites split --shard-count ways; default: "
         "from the CI engine's variables (docs/how-to/shards.md)", &o.shard.index},
        {"--shard-count", "N", Takes::One, shards, "The number of shards (see --shard-index)",
         &o.shard.count},
        {"--durations", "N", Takes::One, shards,
         "Print the N slowest tests after the run (0: all), as pytest does; a value that is not "
         "a number is a REPORT, as --durations-from takes it", &w.durations},
        {"--durations-from", "REPORT", Takes::One, shards,
         "Balance the shards by each suite's time in REPORT, a JUnit or JSON output of an "
         "earlier run, or a --history file (and, on a terminal, give the ETA)", &o.durations},
        {"--merge", "OUT_TYPE:OUT_FILE", Takes::One, shards,
         "Merge the JUnit or JSON REPORTs of a run's shards (the arguments after the options) "
         "into OUT_FILE, and exit", &w.merge},
        {"--expect-shards", "N", Takes::One, shards,
         "With --merge: every shard 0 to N-1 must be there exactly once", &w.expectShards},
        {"--history", "FILE", Takes::One, shards,
         "Append this run to the history in FILE (SQLite, made when missing): each test's "
         "state, time and attempts; the HTML report then shows each test's last 30 runs",
         &o.history},
        {"--history-report", "N", Takes::MaybeOne, shards,
         "With --history: print the flakiest tests, those that failed every run and the most "
         "slowed-down ones of its last N runs (default 30), and exit", &w.historyRuns},
        {"--history-html", "FILE", Takes::One, shards,
         "With --history-report: also write the report as an HTML page to FILE: each test's "
         "outcomes and times over the runs, flaky rate, always failing, slowest, slow-downs and "
         "measurements", &o.historyHtml},
        {"--history-import", "", Takes::Nothing, shards,
         "With --history: load the JUnit or CTRF REPORTs (the arguments after the options; this "
         "runner's or another tool's) into it, one run each, and exit", &w.historyImport},
        {"reports", "REPORT", Takes::Arguments, shards,
         "With --merge: the reports to merge; with --history-import: to load", &o.mergeReports},
    };
    // clang-format on
    return rows;
}

}  // namespace runner
}  // namespace robottestingframework
