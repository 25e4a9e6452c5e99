// The runner's command line: RTF 2.x options (same names, same meaning) and ours.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "runner/plan/selection.h"
#include "runner/plan/shard_of_this_machine.h"

namespace robottestingframework {
namespace runner {

struct OutputRequest {
    std::string type;  // a name of the reporter table (reporter_registry.h)
    std::string file;
};

// --isolation: where the tests run.
enum class Isolation {
    Process,  // "process": each test in a worker process (the default)
    None,     // "none": in the runner's own process, one suite at a time
};

// --color: status words and the closing line in colour.
enum class Colour {
    Auto,    // "auto": on a terminal, unless NO_COLOR is set or TERM is dumb (the default)
    Always,  // "always": also in a pipe or file (CI logs that show colour)
    Never,   // "never"
};

struct Options {
    std::vector<std::string> tests;      // --test/-t FILE
    std::vector<std::string> testDirs;   // --tests DIR
    std::vector<std::string> suites;     // --suite/-s FILE
    std::vector<std::string> suiteDirs;  // --suites DIR
    bool recursive = false;              // --recursive/-r: --tests and --suites descend
    std::string param;                   // --param/-p: for tests without a param of their own
    std::string environment;             // --environment/-e: appended to the suite's
    unsigned int repetition = 0;         // --repetition N; 0: not given
    // --output/-o FILE or TYPE:FILE, with --output-type for the untyped ones. When none is
    // given, RTF 2.x's default applies: result.txt, unless --no-output.
    std::vector<OutputRequest> outputs;
    bool noOutput = false;
    bool noSummary = false;
    bool webReporter = false;              // --web-reporter/-w
    int webPort = 8080;                    // --web-port N; 0: a free port
    std::string webHost = "127.0.0.1";     // --web-host ADDRESS
    double webLinger = 0;                  // --web-linger SECONDS: serve the final page that long
    bool detail = false;                   // --detail/-d: every check on the console
    bool verbose = false;                  // --verbose/-v: reports and output on the console
    std::vector<std::string> commandLine;  // argv as given, for the reports' run facts
    Isolation isolation = Isolation::Process;  // --isolation process|none
    bool privateNetworks = false;      // --network private: every suite in a network of its own
    double timeout = 0;                // --timeout SECONDS for every test; 0: none
    bool watch = false;                // --watch: run again when a file changes
    bool failFast = false;             // --fail-fast: the first failure stops the run
    bool allowEmpty = false;           // --allow-empty: no test selected is a success
    unsigned int retries = 0;          // --retries N: a failing test runs again up to N times
    bool failOnFlaky = false;          // --fail-on-flaky: a flaky test fails the run
    unsigned int repeatUntilFail = 0;  // --repeat-until-fail N; 0: not given (once)
    std::string rerunFailed;           // --rerun-failed REPORT: only the tests it says failed
    // The last run's failures (cli/last_run_cache.h): --lf runs only them, --ff first; the cache
    // folder is --cache-dir DIR (.rtf_cache in the working folder); --no-cache: not read or
    // written.
    bool lastFailed = false;
    bool failedFirst = false;
    std::string cacheDir = ".rtf_cache";
    bool noCache = false;
    std::vector<std::pair<std::string, std::string>> variables;  // --var name=value
    std::vector<std::string> variableFiles;                      // --var-file FILE
    bool list = false;                                           // --list: print, run nothing
    bool listVariables = false;                                  // --list-vars
    Selection selection;                                         // -k, --filter, --(exclude-)tag
    // Shards: --shard-index/--shard-count as given (checked with the environment's, by
    // chooseShard), --durations-from REPORT; --merge TYPE:FILE REPORT... and --expect-shards N.
    ShardFlags shard;
    std::string durations;  // --durations-from: a report, or a --history file
    int slowestTests = -1;  // --durations N: print the N slowest tests (0: all); -1: not asked
    // --history FILE: every run appended to it (SQLite); --history-report [N]: print the
    // flakiest and most slowed-down tests of its last N runs and exit; --history-import:
    // load the REPORTs (JUnit or CTRF, the arguments after the options) into it and exit.
    std::string history;
    bool historyReport = false;
    std::string historyHtml;  // --history-html: the report's HTML page, with --history-report
    unsigned int historyRuns = 30;
    std::vector<std::string> historyImports;
    OutputRequest merge;  // type empty: not merging
    std::vector<std::string> mergeReports;
    unsigned int expectShards = 0;
    unsigned int jobs = 1;  // -j/--jobs N: suites at once; "auto": the machine's cores
    std::string resources;  // --resources FILE: the pools of <resource pool="..."/>
    std::vector<std::string> pluginPath;  // --plugin-path DIR: searched for plug-ins by name
    Colour colour = Colour::Auto;         // --color auto|always|never
    // One world per suite under CTest (docs/how-to/ctest-worlds.md): --world-up DIR sets up the
    // suite's fixtures in a keeper process and returns; --world DIR runs the tests in the world
    // that keeper holds; --world-down DIR stops it. Empty: not given.
    std::string worldUp;
    std::string world;
    std::string worldDown;
    std::string sharedWorlds;  // --shared-worlds DIR (with --world-up)

    bool nothingToRun() const {
        return tests.empty() && testDirs.empty() && suites.empty() && suiteDirs.empty();
    }
};

struct ParseResult {
    enum class Outcome { Run, Exit };
    Outcome outcome = Outcome::Run;
    int status = 0;    // exit status when outcome is Exit: 0 for --help/--version, 2 for errors
    std::string text;  // what to print: help/version on stdout, an error on stderr
};

// The most suites at once (-j): more threads and workers than any machine runs well.
constexpr unsigned long maxJobs = 1024;
// -j/--jobs: a whole number from 1 to maxJobs, or "auto" (the machine's cores). Empty when
// valid (and `jobs` set), else what is expected.
std::string checkJobs(const std::string& text, unsigned int& jobs);

// The output types this build writes.
bool isKnownOutputType(const std::string& type);

// Reads argv into `options`. Never exits and never prints: the caller does, from the result.
ParseResult parseOptions(int argc, const char* const* argv, Options& options);

}  // namespace runner
}  // namespace robottestingframework
