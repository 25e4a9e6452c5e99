#include "runner/cli/options.h"

#include "reporters/reporter_registry.h"
#include "runner/model/value_limits.h"
#include "variables/variables.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <thread>

namespace robottestingframework {
namespace runner {

namespace {

const char* const program = "robottestingframework-testrunner";

// A number check by the rule suite files follow too (value_limits.h); its message says what is
// expected, where CLI11's own would print the type's range.
template <typename Number>
CLI::Validator numberRule(std::string (*check)(const std::string&, Number&),
                          const std::string& what) {
    return CLI::Validator(
        [check](std::string& text) -> std::string {
            Number value{};
            const std::string problem = check(text, value);
            return problem.empty() ? problem : "'" + text + "' " + problem;
        },
        what);
}

bool isTypeWord(const std::string& text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-';
    });
}

std::string checkOutputType(const std::string& type) {
    if (isKnownOutputType(type)) {
        return {};
    }
    return "unknown output type '" + type + "' (expected " + reporters::reporterTypeList() + ")";
}

// How each value of the command line reaches CLI11. A param or an environment is free text
// that often starts with "--" ("--robot icubSim"): it is glued to its option so the parser
// never mistakes it for an option of the runner. RTF 2.x's CMake helper writes
// `-p ${PARAM} -e "${ENV}"`: an empty PARAM vanishes and `-p` is followed by `-e`, which RTF
// 2.0.1 reads as an empty param; so a free-text option followed by an option of the runner
// takes the empty string. An empty value of any other option is an error naming it (an empty
// FILE, N or MODE is never valid), where CLI11 would drop it silently.
const char* const emptyStandIn = "\x1e(empty)\x1e";  // a record separator: typed by no one

struct PreparedArgs {
    std::vector<std::string> args;
    std::string error;  // a usage error found on the way
};

PreparedArgs prepareArgs(const CLI::App& app, int argc, const char* const* argv) {
    std::map<std::string, const CLI::Option*> valueOptions;  // "-p", "--param" -> its option
    std::set<std::string> runnerOptions;                     // every option word of the runner
    for (const CLI::Option* option : app.get_options()) {
        for (const std::string& name : option->get_snames()) {
            runnerOptions.insert("-" + name);
            if (option->get_items_expected_min() > 0) {  // not a flag
                valueOptions["-" + name] = option;
            }
        }
        for (const std::string& name : option->get_lnames()) {
            runnerOptions.insert("--" + name);
            if (option->get_items_expected_min() > 0) {  // not a flag
                valueOptions["--" + name] = option;
            }
        }
    }
    auto isRunnerOption = [&runnerOptions](const std::string& word) {
        return runnerOptions.count(word.substr(0, word.find('='))) > 0;
    };

    PreparedArgs prepared;
    std::vector<std::string>& args = prepared.args;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--") {
            // Everything after "--" stays as it is.
            for (; i < argc; ++i) {
                args.emplace_back(argv[i]);
            }
            break;
        }
        // "--name=value" is read as "--name value".
        std::string name = arg;
        bool glued = false;
        std::string value;
        const std::size_t equals = arg.find('=');
        if (arg.rfind("--", 0) == 0 && equals != std::string::npos) {
            name = arg.substr(0, equals);
            value = arg.substr(equals + 1);
            glued = true;
        }
        // Its N may be left out, but not given empty.
        if (name == "--history-report" &&
            (glued ? value.empty() : i + 1 < argc && argv[i + 1][0] == '\0')) {
            prepared.error = name + ": the value is empty; expected N";
            return prepared;
        }
        const auto found = valueOptions.find(name);
        if (found == valueOptions.end()) {
            args.push_back(arg);
            continue;
        }
        const CLI::Option* option = found->second;
        const std::string longName = option->get_lnames().empty()
                                         ? "-" + option->get_snames().front()
                                         : "--" + option->get_lnames().front();
        const bool freeText = longName == "--param" || longName == "--environment";
        if (!glued) {
            if (i + 1 >= argc) {
                args.push_back(arg);  // CLI11 names the option whose value is missing
                continue;
            }
            if (!freeText || !isRunnerOption(argv[i + 1])) {
                value = argv[++i];
            }  // else `-p -e ...`: an empty param
        }
        if (value.empty() && !freeText) {
            prepared.error = longName + ": the value is empty; expected " + option->get_type_name();
            return prepared;
        }
        if (freeText) {
            // CLI11 takes an empty value for the positional reports: a stand-in goes instead.
            args.push_back(longName + "=" + (value.empty() ? emptyStandIn : value));
        } else {
            args.push_back(arg);
            if (!glued) {
                args.push_back(value);
            }
        }
    }
    return prepared;
}

}  // namespace

std::string checkJobs(const std::string& text, unsigned int& jobs) {
    if (text == "auto") {
        jobs = std::max(1u, std::thread::hardware_concurrency());
        return {};
    }
    const bool digits =
        !text.empty() && text.size() <= 7 &&
        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    const unsigned long value = digits ? std::stoul(text) : 0;
    if (!digits || value < 1 || value > maxJobs) {
        return "expected a whole number of suites at once from 1 to " + std::to_string(maxJobs) +
               ", or auto";
    }
    jobs = static_cast<unsigned int>(value);
    return {};
}

bool isKnownOutputType(const std::string& type) {
    return reporters::findReporterType(type) != nullptr;
}

ParseResult parseOptions(int argc, const char* const* argv, Options& options) {
    CLI::App app{"Runs Robot Testing Framework test cases and suites.", program};
    app.footer(
        "Exit status: 0 when every test passed (skipped ones allowed), 1 when a test failed, "
        "errored, crashed, timed out or could not be loaded, or a fixture failed, 2 on a usage "
        "or configuration error (bad option, unreadable or malformed suite file, unknown "
        "dependency, an output that could not be written), 5 when no test is selected "
        "(unless --allow-empty), 130 when interrupted by Ctrl-C "
        "(SIGINT), 143 when stopped by SIGTERM.");
    app.option_defaults()->always_capture_default(false);
    // RTF 2.x's documentation lists -? beside --help.
    app.set_help_flag("-h,-?,--help", "Print this help message and exit");
    options.commandLine.assign(argv, argv + argc);

    std::vector<std::string> outputs;
    std::string outputType = "text";
    std::vector<std::string> variables;
    bool version = false;

    auto takeAll = [](CLI::Option* option) {
        option->type_size(1)->expected(1)->allow_extra_args(false)->multi_option_policy(
            CLI::MultiOptionPolicy::TakeAll);
    };
    takeAll(app.add_option("-t,--test", options.tests, "Run the test case in FILE (repeatable)")
                ->type_name("FILE"));
    takeAll(app.add_option("--tests", options.testDirs, "Run every test case in the folder DIR")
                ->type_name("DIR"));
    takeAll(
        app.add_option("-s,--suite", options.suites, "Run the suite in the XML FILE (repeatable)")
            ->type_name("FILE"));
    takeAll(
        app.add_option("--suites", options.suiteDirs, "Run every suite (*.xml) in the folder DIR")
            ->type_name("DIR"));
    app.add_flag("-r,--recursive", options.recursive,
                 "--tests and --suites look in sub-folders too");
    app.add_option("-p,--param", options.param, "Param for the tests that have none of their own")
        ->type_name("TEXT");
    app.add_option("-e,--environment", options.environment,
                   "Environment for every test, after the suite's own")
        ->type_name("TEXT");
    app.add_option("--repetition", options.repetition,
                   "Run each test N times (a test's own repetition wins)")
        ->type_name("N")
        ->check(numberRule(checkRepetition, "from 1 to " + std::to_string(maxRepetition)));
    takeAll(app.add_option("-o,--output", outputs,
                           "Write the results to FILE, or TYPE:FILE (e.g. junit:results.xml; "
                           "- or /dev/stdout: the standard output, the console then going to "
                           "stderr); repeatable. Default: result.txt")
                ->type_name("FILE"));
    app.add_option("--output-type", outputType,
                   "Type of the --output files without a TYPE: " + reporters::reporterTypeList() +
                       " (default text)")
        ->type_name("TYPE");
    app.add_flag("--no-output", options.noOutput, "Write no result file");
    app.add_flag("--no-summary", options.noSummary,
                 "Leave the summary out of the console and the text output");
    app.add_flag("-w,--web-reporter", options.webReporter, "Show the run live in a web page");
    app.add_option("--web-port", options.webPort,
                   "Port of the web reporter (default 8080; 0 picks a free one)")
        ->type_name("N")
        ->check(CLI::Range(0, 65535));
    app.add_option("--web-host", options.webHost,
                   "Address the web reporter listens on (default 127.0.0.1, this machine only)")
        ->type_name("ADDRESS");
    app.add_option("--web-linger", options.webLinger,
                   "Keep serving the final web page this long after the run (default 0: exit "
                   "when the run ends)")
        ->type_name("SECONDS")
        ->check(numberRule(checkSeconds,
                           "from 0 to " + std::to_string(static_cast<long>(maxTimeoutSeconds))));
    app.add_flag("-d,--detail", options.detail, "Show every check on the console");
    app.add_flag("-v,--verbose", options.verbose,
                 "Show the tests' reports and what they print on the console");
    std::string isolation = "process";
    app.add_option("--isolation", isolation,
                   "Where tests run: process (each in a worker process; the default) or none "
                   "(in the runner's process)")
        ->type_name("MODE")
        ->check(CLI::IsMember({"none", "process"}));
    std::string network = "host";
    app.add_option("--network", network,
                   "private: every suite runs in a network of its own, loopback only, so suites "
                   "side by side bind the same fixed ports (Linux); host: the machine's network, "
                   "unless a suite says network=\"private\" (the default)")
        ->type_name("NETWORK")
        ->check(CLI::IsMember({"private", "host"}));
    app.add_option("--world-up", options.worldUp,
                   "Set up the suite's fixtures (its world, and its private network) in a keeper "
                   "process that outlives this one, with its control socket in DIR; exit 0 when "
                   "the world is up, 1 with the reason when it failed. The keeper stops its world "
                   "when the process that started the runner (ctest) ends (docs/ctest-worlds.md)")
        ->type_name("DIR");
    app.add_option("--world", options.world,
                   "Run the suite's tests in the world a --world-up DIR keeper holds, without "
                   "setting up the suite's fixtures; exit 2 when no keeper is there")
        ->type_name("DIR");
    app.add_option("--world-down", options.worldDown,
                   "Stop the world the --world-up DIR keeper holds and print its tear-down; "
                   "exit 1 when the tear-down failed")
        ->type_name("DIR");
    app.add_option("--timeout", options.timeout,
                   "Time limit of each test, set-up and tear-down included; a suite's <timeout> "
                   "and a test's timeout=\"...\" win (default: none)")
        ->type_name("SECONDS")
        ->check(numberRule(checkSeconds, "from 0 (no limit) to " +
                                             std::to_string(static_cast<long>(maxTimeoutSeconds))));
    app.add_flag("--allow-empty", options.allowEmpty,
                 "A run with no test selected (by --filter, --tag, --rerun-failed, or suites "
                 "without tests) exits 0 instead of 5");
    app.add_flag("--fail-fast", options.failFast,
                 "Stop the run at the first failure; the remaining tests are skipped");
    app.add_option("--retries", options.retries,
                   "Run a failing test again up to N times; one that passes on a later attempt "
                   "is flaky (default 0)")
        ->type_name("N")
        ->check(numberRule(checkRetries, "from 0 to " + std::to_string(maxRetries)));
    app.add_flag("--fail-on-flaky", options.failOnFlaky,
                 "A flaky test fails the run (exit status 1)");
    app.add_option("--rerun-failed", options.rerunFailed,
                   "Run only the tests that failed, errored, crashed or timed out in REPORT, a "
                   "JUnit or JSON output of an earlier run")
        ->type_name("REPORT");
    app.add_option("--repeat-until-fail", options.repeatUntilFail,
                   "Run the selection up to N times, stopping after the first run that fails")
        ->type_name("N")
        ->check(numberRule(checkRepetition, "from 1 to " + std::to_string(maxRepetition)));
    takeAll(app.add_option("--var", variables,
                           "Set the variable NAME, used as ${NAME} in suites, test files and "
                           "world files; wins over --var-file and the files' own (repeatable)")
                ->type_name("NAME=VALUE"));
    takeAll(app.add_option("--var-file", options.variableFiles,
                           "Read variables from FILE, NAME=VALUE per line, # comments; a later "
                           "file wins (repeatable)")
                ->type_name("FILE"));
    app.add_flag("--list", options.list,
                 "Print what would run (suite, test, type, plug-in, param, tags, timeout) and "
                 "exit without loading or starting anything; --output json:FILE writes it as "
                 "JSON");
    app.add_flag("--list-vars", options.listVariables,
                 "Print each suite's variables, their values and where they come from, and exit");
    std::vector<std::string> tags;
    std::vector<std::string> excludedTags;
    std::vector<std::string> filters;
    takeAll(app.add_option("--tag", tags,
                           "Run only the tests whose tags match EXPR: a tag or pattern (*, ?), "
                           "with AND, OR, NOT (e.g. armANDslow, 'arm OR leg', 'NOT slow'); "
                           "repeatable, any may match")
                ->type_name("EXPR"));
    takeAll(app.add_option("--exclude-tag", excludedTags,
                           "Leave out the tests whose tags match EXPR (repeatable)")
                ->type_name("EXPR"));
    takeAll(app.add_option("--filter", filters,
                           "Run only the tests whose id (suite/test, as --list shows it) "
                           "matches: patterns with * and ?, separated by ':', negative ones "
                           "after '-' (e.g. 'arm/*-*slow*'); '\\' makes the next character "
                           "literal ('arm/*\\-fast'); a test's id written as it is selects "
                           "that test alone")
                ->type_name("PATTERN"));
    app.add_option("--shard-index", options.shard.index,
                   "Run only shard I (from 0) of the selected suites split --shard-count ways; "
                   "default: from the CI engine's variables (see the README)")
        ->type_name("I");
    app.add_option("--shard-count", options.shard.count, "The number of shards (see --shard-index)")
        ->type_name("N");
    std::string durations;
    app.add_option("--durations", durations,
                   "Print the N slowest tests after the run (0: all), as pytest does; a value "
                   "that is not a number is a REPORT, as --durations-from takes it")
        ->type_name("N");
    app.add_option("--durations-from", options.durations,
                   "Balance the shards by each suite's time in REPORT, a JUnit or JSON output of "
                   "an earlier run, or a --history file (and, on a terminal, give the ETA)")
        ->type_name("REPORT");
    app.add_option("--history", options.history,
                   "Append this run to the history in FILE (SQLite, made when missing): each "
                   "test's state, time and attempts; the HTML report then shows each test's "
                   "last 30 runs")
        ->type_name("FILE");
    std::string historyRuns;
    CLI::Option* historyReportOption =
        app.add_option("--history-report", historyRuns,
                       "With --history: print the flakiest and the most slowed-down tests of "
                       "its last N runs (default 30), and exit")
            ->expected(0, 1)
            ->type_name("N");
    bool historyImport = false;
    app.add_flag("--history-import", historyImport,
                 "With --history: load the JUnit or CTRF REPORTs (the arguments after the "
                 "options; this runner's or another tool's) into it, one run each, and exit");
    std::string merge;
    std::string expectShards;
    app.add_option("--merge", merge,
                   "Merge the JUnit or JSON REPORTs of a run's shards (the arguments after the "
                   "options) into OUT_FILE, and exit")
        ->type_name("OUT_TYPE:OUT_FILE");
    CLI::Option* expectShardsOption =
        app.add_option("--expect-shards", expectShards,
                       "With --merge: every shard 0 to N-1 must be there exactly once")
            ->type_name("N");
    app.add_option("reports", options.mergeReports,
                   "With --merge: the reports to merge; with --history-import: to load")
        ->type_name("REPORT");
    std::string jobs;
    app.add_option("-j,--jobs", jobs,
                   "Run up to N suites at once, each with its own fixtures; 'auto': one per "
                   "core (default 1)")
        ->type_name("N");
    app.add_option("--resources", options.resources,
                   "The pools <resource pool=\"...\"/> takes items from: a JSON file shaped "
                   "like CTest's resource spec file")
        ->type_name("FILE");
    takeAll(app.add_option("--plugin-path", options.pluginPath,
                           "Look plug-ins named without a folder up in DIR too: after the "
                           "suite's folder, before RTF_PLUGIN_PATH and the system's library "
                           "path (repeatable, in order)")
                ->type_name("DIR"));
    std::string colour = "auto";
    app.add_option("--color", colour,
                   "Colour on the console: auto (on a terminal, unless NO_COLOR is set), "
                   "always, never (default auto)")
        ->type_name("WHEN");
    app.add_flag("--version", version, "Print the version and exit");

    ParseResult result;
    auto usageError = [&result](const std::string& message) {
        result.outcome = ParseResult::Outcome::Exit;
        result.status = 2;
        result.text = std::string(program) + ": " + message + "\nRun '" + program +
                      " --help' for the options.\n";
        return result;
    };

    PreparedArgs prepared = prepareArgs(app, argc, argv);
    if (!prepared.error.empty()) {
        return usageError(prepared.error);
    }
    std::vector<std::string>& args = prepared.args;
    std::reverse(args.begin(), args.end());  // CLI11 takes them last first
    try {
        app.parse(args);
    } catch (const CLI::CallForHelp&) {
        result.outcome = ParseResult::Outcome::Exit;
        result.status = 0;
        result.text = app.help();
        return result;
    } catch (const CLI::ParseError& e) {
        return usageError(e.what());
    }

    for (std::string* text : {&options.param, &options.environment}) {
        if (*text == emptyStandIn) {
            text->clear();
        }
    }

    if (version) {
        result.outcome = ParseResult::Outcome::Exit;
        result.status = 0;
        result.text = std::string(program) + " " + RTF_VERSION + "\n";
        return result;
    }

    options.isolation = isolation == "none" ? Isolation::None : Isolation::Process;
    options.privateNetworks = network == "private";
    if ((options.worldUp.empty() ? 0 : 1) + (options.world.empty() ? 0 : 1) +
            (options.worldDown.empty() ? 0 : 1) >
        1) {
        return usageError("--world-up, --world and --world-down: one at a time");
    }

    if (!jobs.empty()) {
        const std::string problem = checkJobs(jobs, options.jobs);
        if (!problem.empty()) {
            return usageError("--jobs " + jobs + ": " + problem);
        }
    }

    std::string problem = checkOutputType(outputType);
    if (!problem.empty()) {
        return usageError("--output-type: " + problem);
    }
    for (const auto& output : outputs) {
        OutputRequest request{outputType, output};
        // A word before the first colon is a type, known or not ("junti:x.xml" is a typo, not
        // a file name); "text:a:b" or "./a:b" writes a file whose name has a colon.
        std::size_t colon = output.find(':');
        if (colon != std::string::npos && isTypeWord(output.substr(0, colon))) {
            std::string type = output.substr(0, colon);
            problem = checkOutputType(type);
            if (!problem.empty()) {
                return usageError("--output " + output + ": " + problem +
                                  "; a file whose name has a colon is written as text:" + output +
                                  " or ./" + output);
            }
            request = OutputRequest{type, output.substr(colon + 1)};
        }
        if (request.file.empty()) {
            return usageError("--output " + output + ": no file name");
        }
        options.outputs.push_back(request);
    }
    if (options.outputs.empty() && !options.noOutput) {
        // RTF 2.x writes a result file unless told not to.
        options.outputs.push_back(
            OutputRequest{outputType, reporters::findReporterType(outputType)->defaultFile});
    }
    if (options.noOutput) {
        options.outputs.clear();
    }

    for (const auto& variable : variables) {
        std::string name;
        std::string value;
        std::string error;
        if (!variables::parseAssignment(variable, name, value, error)) {
            return usageError("--var " + variable + ": " + error);
        }
        options.variables.emplace_back(name, value);
    }

    for (const auto& group :
         {std::make_pair("--tag", &tags), std::make_pair("--exclude-tag", &excludedTags)}) {
        for (const auto& text : *group.second) {
            TagExpression expression;
            std::string error;
            if (!TagExpression::parse(text, expression, error)) {
                return usageError(std::string(group.first) + " " + text + ": " + error);
            }
            (group.second == &tags ? options.selection.include : options.selection.exclude)
                .push_back(std::move(expression));
        }
    }
    for (const auto& text : filters) {
        NameFilter filter;
        std::string error;
        if (!NameFilter::parse(text, filter, error)) {
            // Maybe a test's id, which wins over pattern syntax: told once the suites are read.
            filter = NameFilter::exactIdOnly(text, error);
        }
        options.selection.filters.push_back(std::move(filter));
    }

    if (!durations.empty()) {
        // A number is pytest's --durations N; anything else the REPORT of earlier 3.0 builds.
        if (durations.size() <= 9 && std::all_of(durations.begin(), durations.end(),
                                                 [](char c) { return c >= '0' && c <= '9'; })) {
            options.slowestTests = std::stoi(durations);
        } else if (!options.durations.empty()) {
            return usageError("--durations " + durations + " and --durations-from " +
                              options.durations +
                              ": one REPORT at most (--durations N prints "
                              "the N slowest tests)");
        } else {
            options.durations = durations;
        }
    }
    if (expectShardsOption->count() > 0 && merge.empty()) {
        return usageError("--expect-shards needs --merge");
    }
    if (colour == "auto") {
        options.colour = Colour::Auto;
    } else if (colour == "always") {
        options.colour = Colour::Always;
    } else if (colour == "never") {
        options.colour = Colour::Never;
    } else {
        return usageError("--color " + colour + ": expected auto, always or never");
    }
    const bool historyCommand = historyImport || historyReportOption->count() > 0;
    if (historyCommand && options.history.empty()) {
        return usageError(std::string(historyImport ? "--history-import" : "--history-report") +
                          " needs --history FILE");
    }
    if (historyReportOption->count() > 0) {
        options.historyReport = true;
        if (!historyRuns.empty()) {
            if (historyRuns.size() > 6 ||
                historyRuns.find_first_not_of("0123456789") != std::string::npos ||
                std::stoul(historyRuns) == 0) {
                return usageError("--history-report '" + historyRuns +
                                  "': expected a whole number of runs from 1 to 999999");
            }
            options.historyRuns = static_cast<unsigned int>(std::stoul(historyRuns));
        }
    }
    if (historyImport) {
        if (!merge.empty()) {
            return usageError("--history-import and --merge: give one of them");
        }
        if (options.mergeReports.empty()) {
            return usageError("--history-import: no report to load");
        }
        options.historyImports = std::move(options.mergeReports);
        options.mergeReports.clear();
    }
    if (!options.mergeReports.empty() && merge.empty()) {
        return usageError("unexpected argument " + options.mergeReports.front() +
                          " (reports are given only to --merge and --history-import)");
    }
    if (historyCommand) {
        return result;  // nothing else is read by a command of the history
    }
    if (!merge.empty()) {
        const std::size_t colon = merge.find(':');
        const std::string type = colon == std::string::npos ? "" : merge.substr(0, colon);
        if ((type != "junit" && type != "json") || colon + 1 >= merge.size()) {
            return usageError("--merge " + merge + ": expected junit:FILE or json:FILE");
        }
        options.merge = OutputRequest{type, merge.substr(colon + 1)};
        if (options.mergeReports.empty()) {
            return usageError("--merge " + merge + ": no report to merge");
        }
        if (expectShardsOption->count() > 0) {
            unsigned long count = 0;
            if (expectShards.empty() || expectShards.size() > 9 ||
                expectShards.find_first_not_of("0123456789") != std::string::npos ||
                (count = std::stoul(expectShards)) == 0 || count > maxShards) {
                return usageError("--expect-shards '" + expectShards +
                                  "': expected a whole number of shards from 1 to " +
                                  std::to_string(maxShards));
            }
            options.expectShards = static_cast<unsigned int>(count);
        }
        return result;  // nothing else is read when merging
    }
    if (options.nothingToRun()) {
        return usageError("nothing to run: give --test, --tests, --suite or --suites");
    }
    return result;
}

}  // namespace runner
}  // namespace robottestingframework
