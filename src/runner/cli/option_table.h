// The runner's options, each once: its names, its value, its help, its group in --help and
// where it goes. The parser (options.cpp), --help, the man page and docs/reference/
// command-line.md (option_docs.h) are all made from this table: a new option is a row of
// optionTable() and, when its value needs reading after the parse, a step of options.cpp.
#pragma once

#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "runner/cli/options.h"

namespace robottestingframework {
namespace runner {

// The words of the command line that are read after the parse (options.cpp turns them into
// Options): a type or file of --output, a NAME=VALUE of --var, a tag expression, ...
struct CommandLineWords {
    std::vector<std::string> outputs;
    std::string outputType = "text";
    std::vector<std::string> variables;
    std::vector<std::string> tags;
    std::vector<std::string> excludedTags;
    std::vector<std::string> filters;
    std::string keyword;    // -k EXPR
    std::string durations;  // --durations: N, or a REPORT as --durations-from takes it
    std::string historyRuns;
    bool historyImport = false;
    std::string merge;
    std::string expectShards;
    std::string jobs;
    std::string colour = "auto";
    std::string isolation = "process";
    std::string network = "host";
    bool version = false;
    bool helpMan = false;       // --help-man: the man page, for the build
    bool helpMarkdown = false;  // --help-markdown: docs/reference/command-line.md
};

// A rule for an option's value, checked by the parser.
struct ValueRule {
    std::function<std::string(std::string&)> check;  // an error ("'x' is not ..."), or empty
    std::string expected;  // what it expects, shown after the value word in --help (CLI11's way)
};

struct OptionRow {
    enum class Takes {
        Nothing,     // a flag
        One,         // one value; given twice is an error
        Repeatable,  // one value each time, all kept in order
        MaybeOne,    // a value that may be left out (--history-report [N])
        Arguments,   // the arguments after the options (no name of its own)
        Help,        // -h, -?, --help: CLI11's help flag
    };
    // CLI11's spelling: short and long names, RTF 2.x's aliases among them ("-h,-?,--help").
    std::string names;
    std::string value;  // the value's word in --help (FILE, N); empty for a flag
    Takes takes = Takes::Nothing;
    std::string group;  // the heading in --help and the man page; empty: hidden
    std::string help;
    // Where the value goes: a field of Options or of CommandLineWords.
    std::variant<std::monostate, bool*, int*, unsigned int*, double*, std::string*,
                 std::vector<std::string>*>
        into{};
    ValueRule rule{};       // none: any value
    bool fromRtf2 = false;  // RTF 2.x's runner has it, with the same names and meaning
    // A free text ("--robot icubSim"): taken even when it starts with "--", and empty when
    // the next word is an option of the runner (RTF 2.x's `-p ${PARAM} -e "${ENV}"`).
    bool freeText = false;

    // "--test" (the first long name), or the first short one when there is no long one.
    std::string longName() const;
    // Every name as typed ("-t", "--test"); none for the Arguments row.
    std::vector<std::string> spelledNames() const;
};

// The first line of --help and the man page's NAME, and what follows the options.
extern const char* const programSummary;
extern const char* const exitStatusHelp;

// The rows in --help order; `options` and `words` receive the values.
std::vector<OptionRow> optionTable(Options& options, CommandLineWords& words);

}  // namespace runner
}  // namespace robottestingframework
