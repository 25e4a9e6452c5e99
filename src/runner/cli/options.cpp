#include "runner/cli/options.h"

#include "reporters/reporter_registry.h"
#include "runner/cli/option_docs.h"
#include "runner/cli/option_table.h"
#include "variables/variables.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <map>
#include <thread>
#include <type_traits>

namespace robottestingframework {
namespace runner {

namespace {

const char* const program = "robottestingframework-testrunner";

// The value's word as CLI11 shows it: "N:from 1 to 1000000000".
std::string valueWord(const OptionRow& row) {
    return row.rule.expected.empty() ? row.value : row.value + ":" + row.rule.expected;
}

// One row of the table into the CLI11 app.
void addRow(CLI::App& app, const OptionRow& row) {
    if (row.takes == OptionRow::Takes::Help) {
        app.set_help_flag(row.names, row.help)->group(row.group);
        return;
    }
    CLI::Option* option = std::visit(
        [&app, &row](auto into) -> CLI::Option* {
            using Into = decltype(into);
            if constexpr (std::is_same_v<Into, std::monostate>) {
                return nullptr;
            } else if constexpr (std::is_same_v<Into, bool*>) {
                return app.add_flag(row.names, *into, row.help);
            } else {
                return app.add_option(row.names, *into, row.help);
            }
        },
        row.into);
    if (option == nullptr) {
        return;
    }
    if (row.takes != OptionRow::Takes::Arguments) {
        option->group(row.group);  // an empty group hides the option
    }
    if (row.takes == OptionRow::Takes::Nothing) {
        return;
    }
    option->type_name(row.value);
    if (row.takes == OptionRow::Takes::Repeatable) {
        option->type_size(1)->expected(1)->allow_extra_args(false)->multi_option_policy(
            CLI::MultiOptionPolicy::TakeAll);
    } else if (row.takes == OptionRow::Takes::MaybeOne) {
        option->expected(0, 1);
    }
    if (row.rule.check) {
        option->check(CLI::Validator(row.rule.check, row.rule.expected));
    }
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

PreparedArgs prepareArgs(const std::vector<OptionRow>& rows, int argc, const char* const* argv) {
    std::map<std::string, const OptionRow*> byName;  // "-p", "--param" -> its row
    for (const OptionRow& row : rows) {
        for (const std::string& name : row.spelledNames()) {
            byName[name] = &row;
        }
    }
    auto isRunnerOption = [&byName](const std::string& word) {
        return byName.count(word.substr(0, word.find('='))) > 0;
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
        const auto found = byName.find(name);
        const OptionRow* row = found == byName.end() ? nullptr : found->second;
        // Its N may be left out, but not given empty.
        if (row != nullptr && row->takes == OptionRow::Takes::MaybeOne &&
            (glued ? value.empty() : i + 1 < argc && argv[i + 1][0] == '\0')) {
            prepared.error = name + ": the value is empty; expected " + row->value;
            return prepared;
        }
        if (row == nullptr ||
            (row->takes != OptionRow::Takes::One && row->takes != OptionRow::Takes::Repeatable)) {
            args.push_back(arg);
            continue;
        }
        const std::string longName = row->longName();
        if (!glued) {
            if (i + 1 >= argc) {
                args.push_back(arg);  // CLI11 names the option whose value is missing
                continue;
            }
            if (!row->freeText || !isRunnerOption(argv[i + 1])) {
                value = argv[++i];
            }  // else `-p -e ...`: an empty param
        }
        if (value.empty() && !row->freeText) {
            prepared.error = longName + ": the value is empty; expected " + valueWord(*row);
            return prepared;
        }
        if (row->freeText) {
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

ParseResult exitWith(int status, std::string text) {
    ParseResult result;
    result.outcome = ParseResult::Outcome::Exit;
    result.status = status;
    result.text = std::move(text);
    return result;
}

ParseResult usageError(const std::string& message) {
    return exitWith(2, std::string(program) + ": " + message + "\nRun '" + program +
                           " --help' for the options.\n");
}

// The steps that read the words of CommandLineWords into Options, in this order; each returns
// a usage error, or empty.

std::string readRunShape(const CommandLineWords& words, Options& options) {
    options.isolation = words.isolation == "none" ? Isolation::None : Isolation::Process;
    options.privateNetworks = words.network == "private";
    if ((options.worldUp.empty() ? 0 : 1) + (options.world.empty() ? 0 : 1) +
            (options.worldDown.empty() ? 0 : 1) >
        1) {
        return "--world-up, --world and --world-down: one at a time";
    }
    if (!options.sharedWorlds.empty() && options.worldUp.empty()) {
        return "--shared-worlds " + options.sharedWorlds + ": only with --world-up DIR";
    }
    if (!words.jobs.empty()) {
        const std::string problem = checkJobs(words.jobs, options.jobs);
        if (!problem.empty()) {
            return "--jobs " + words.jobs + ": " + problem;
        }
    }
    return {};
}

std::string readOutputs(const CommandLineWords& words, Options& options) {
    std::string problem = checkOutputType(words.outputType);
    if (!problem.empty()) {
        return "--output-type: " + problem;
    }
    for (const auto& output : words.outputs) {
        OutputRequest request{words.outputType, output};
        // A word before the first colon is a type, known or not ("junti:x.xml" is a typo, not
        // a file name); "text:a:b" or "./a:b" writes a file whose name has a colon.
        std::size_t colon = output.find(':');
        if (colon != std::string::npos && isTypeWord(output.substr(0, colon))) {
            std::string type = output.substr(0, colon);
            problem = checkOutputType(type);
            if (!problem.empty()) {
                return "--output " + output + ": " + problem +
                       "; a file whose name has a colon is written as text:" + output + " or ./" +
                       output;
            }
            request = OutputRequest{type, output.substr(colon + 1)};
        }
        if (request.file.empty()) {
            return "--output " + output + ": no file name";
        }
        options.outputs.push_back(request);
    }
    if (options.outputs.empty() && !options.noOutput) {
        // RTF 2.x writes a result file unless told not to.
        options.outputs.push_back(OutputRequest{
            words.outputType, reporters::findReporterType(words.outputType)->defaultFile});
    }
    if (options.noOutput) {
        options.outputs.clear();
    }
    return {};
}

std::string readVariables(const CommandLineWords& words, Options& options) {
    for (const auto& variable : words.variables) {
        std::string name;
        std::string value;
        std::string error;
        if (!variables::parseAssignment(variable, name, value, error)) {
            return "--var " + variable + ": " + error;
        }
        options.variables.emplace_back(name, value);
    }
    return {};
}

std::string readSelection(const CommandLineWords& words, Options& options) {
    for (const auto& group : {std::make_pair("--tag", &words.tags),
                              std::make_pair("--exclude-tag", &words.excludedTags)}) {
        for (const auto& text : *group.second) {
            TagExpression expression;
            std::string error;
            if (!TagExpression::parse(text, expression, error)) {
                return std::string(group.first) + " " + text + ": " + error;
            }
            (group.second == &words.tags ? options.selection.include : options.selection.exclude)
                .push_back(std::move(expression));
        }
    }
    if (!words.keyword.empty()) {
        KeywordExpression expression;
        std::string error;
        if (!KeywordExpression::parse(words.keyword, expression, error)) {
            return "-k '" + words.keyword + "': " + error;
        }
        options.selection.keywords.push_back(std::move(expression));
    }
    for (const auto& text : words.filters) {
        NameFilter filter;
        std::string error;
        if (!NameFilter::parse(text, filter, error)) {
            // Maybe a test's id, which wins over pattern syntax: told once the suites are read.
            filter = NameFilter::exactIdOnly(text, error);
        }
        options.selection.filters.push_back(std::move(filter));
    }
    return {};
}

std::string readColour(const CommandLineWords& words, Options& options) {
    if (words.colour == "auto") {
        options.colour = Colour::Auto;
    } else if (words.colour == "always") {
        options.colour = Colour::Always;
    } else if (words.colour == "never") {
        options.colour = Colour::Never;
    } else {
        return "--color " + words.colour + ": expected auto, always or never";
    }
    return {};
}

// --history-report, --history-import and --merge: commands of their own, which read nothing
// else (`command` set when one is given).
std::string readCommands(CommandLineWords& words, const CLI::App& app, Options& options,
                         bool& command) {
    const bool historyReport = app.count("--history-report") > 0;
    const bool historyCommand = words.historyImport || historyReport;
    if (historyCommand && options.history.empty()) {
        return std::string(words.historyImport ? "--history-import" : "--history-report") +
               " needs --history FILE";
    }
    if (!options.historyHtml.empty() && !historyReport) {
        return "--history-html needs --history-report";
    }
    if (historyReport) {
        options.historyReport = true;
        const std::string& runs = words.historyRuns;
        if (!runs.empty()) {
            if (runs.size() > 6 || runs.find_first_not_of("0123456789") != std::string::npos ||
                std::stoul(runs) == 0) {
                return "--history-report '" + runs +
                       "': expected a whole number of runs from 1 to 999999";
            }
            options.historyRuns = static_cast<unsigned int>(std::stoul(runs));
        }
    }
    if (words.historyImport) {
        if (!words.merge.empty()) {
            return "--history-import and --merge: give one of them";
        }
        if (options.mergeReports.empty()) {
            return "--history-import: no report to load";
        }
        options.historyImports = std::move(options.mergeReports);
        options.mergeReports.clear();
    }
    if (!options.mergeReports.empty() && words.merge.empty()) {
        return "unexpected argument " + options.mergeReports.front() +
               " (reports are given only to --merge and --history-import)";
    }
    command = historyCommand || !words.merge.empty();
    if (historyCommand || words.merge.empty()) {
        return {};
    }
    const std::string& merge = words.merge;
    const std::size_t colon = merge.find(':');
    const std::string type = colon == std::string::npos ? "" : merge.substr(0, colon);
    if ((type != "junit" && type != "json") || colon + 1 >= merge.size()) {
        return "--merge " + merge + ": expected junit:FILE or json:FILE";
    }
    options.merge = OutputRequest{type, merge.substr(colon + 1)};
    if (options.mergeReports.empty()) {
        return "--merge " + merge + ": no report to merge";
    }
    if (app.count("--expect-shards") > 0) {
        const std::string& shards = words.expectShards;
        unsigned long count = 0;
        if (shards.empty() || shards.size() > 9 ||
            shards.find_first_not_of("0123456789") != std::string::npos ||
            (count = std::stoul(shards)) == 0 || count > maxShards) {
            return "--expect-shards '" + shards +
                   "': expected a whole number of shards from 1 to " + std::to_string(maxShards);
        }
        options.expectShards = static_cast<unsigned int>(count);
    }
    return {};
}

// --durations N (pytest's: print the N slowest tests), or a REPORT as --durations-from takes
// it (the form of earlier 3.0 builds).
std::string readDurations(const CommandLineWords& words, Options& options) {
    const std::string& durations = words.durations;
    if (durations.empty()) {
        return {};
    }
    if (durations.size() <= 9 && std::all_of(durations.begin(), durations.end(),
                                             [](char c) { return c >= '0' && c <= '9'; })) {
        options.slowestTests = std::stoi(durations);
    } else if (!options.durations.empty()) {
        return "--durations " + durations + " and --durations-from " + options.durations +
               ": one REPORT at most (--durations N prints the N slowest tests)";
    } else {
        options.durations = durations;
    }
    return {};
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
    CLI::App app{programSummary, program};
    app.footer(exitStatusHelp);
    app.option_defaults()->always_capture_default(false);
    options.commandLine.assign(argv, argv + argc);
    CommandLineWords words;
    const std::vector<OptionRow> rows = optionTable(options, words);
    for (const OptionRow& row : rows) {
        addRow(app, row);
    }

    PreparedArgs prepared = prepareArgs(rows, argc, argv);
    if (!prepared.error.empty()) {
        return usageError(prepared.error);
    }
    std::vector<std::string>& args = prepared.args;
    std::reverse(args.begin(), args.end());  // CLI11 takes them last first
    try {
        app.parse(args);
    } catch (const CLI::CallForHelp&) {
        return exitWith(0, app.help());
    } catch (const CLI::ParseError& e) {
        return usageError(e.what());
    }
    for (std::string* text : {&options.param, &options.environment}) {
        if (*text == emptyStandIn) {
            text->clear();
        }
    }
    if (words.version) {
        return exitWith(0, std::string(program) + " " + RTF_VERSION + "\n");
    }
    if (words.helpMan || words.helpMarkdown) {
        return exitWith(0, words.helpMan ? manPage(rows, RTF_VERSION) : markdownReference(rows));
    }

    for (auto step : {readRunShape, readOutputs, readVariables, readSelection, readDurations}) {
        const std::string error = step(words, options);
        if (!error.empty()) {
            return usageError(error);
        }
    }
    if ((options.lastFailed || options.failedFirst) && options.noCache) {
        return usageError(std::string(options.lastFailed ? "--lf" : "--ff") +
                          " reads the cache folder, which --no-cache turns off");
    }
    if (options.lastFailed && !options.rerunFailed.empty()) {
        return usageError("--lf and --rerun-failed both choose the tests to rerun: give one");
    }
    if (app.count("--expect-shards") > 0 && words.merge.empty()) {
        return usageError("--expect-shards needs --merge");
    }
    std::string error = readColour(words, options);
    bool command = false;
    if (error.empty()) {
        error = readCommands(words, app, options, command);
    }
    if (!error.empty()) {
        return usageError(error);
    }
    if (!command && options.nothingToRun()) {
        return usageError("nothing to run: give --test, --tests, --suite or --suites");
    }
    return ParseResult{};
}

}  // namespace runner
}  // namespace robottestingframework
