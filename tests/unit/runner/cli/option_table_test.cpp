// The runner's option table (option_table.h): every option once, named, with its help, and
// the man page and the reference made from it name every option.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "runner/cli/option_docs.h"
#include "runner/cli/option_table.h"

using robottestingframework::runner::CommandLineWords;
using robottestingframework::runner::manPage;
using robottestingframework::runner::markdownReference;
using robottestingframework::runner::OptionRow;
using robottestingframework::runner::Options;
using robottestingframework::runner::optionTable;
using robottestingframework::runner::parseOptions;
using robottestingframework::runner::ParseResult;

namespace {

std::vector<OptionRow> table() {
    static Options options;
    static CommandLineWords words;
    return optionTable(options, words);
}

// roff writes a dash as "\-".
std::string asRoff(const std::string& name) {
    std::string out;
    for (char c : name) {
        out += c == '-' ? std::string("\\-") : std::string(1, c);
    }
    return out;
}

}  // namespace

TEST(OptionTable, EveryOptionHasNamesHelpAndADestination) {
    for (const OptionRow& row : table()) {
        SCOPED_TRACE(row.names);
        EXPECT_FALSE(row.help.empty());
        if (row.takes == OptionRow::Takes::Arguments) {
            EXPECT_TRUE(row.spelledNames().empty());
        } else {
            EXPECT_FALSE(row.spelledNames().empty());
            EXPECT_EQ(row.longName().rfind("--", 0), 0u) << "every option has a long name";
        }
        for (const std::string& name : row.spelledNames()) {
            EXPECT_TRUE(name.size() == 2 ? name[0] == '-' : name.rfind("--", 0) == 0) << name;
        }
        // A flag has no value word; everything else has one.
        EXPECT_EQ(row.value.empty(),
                  row.takes == OptionRow::Takes::Nothing || row.takes == OptionRow::Takes::Help);
        // Only the help flag goes nowhere (CLI11 answers it).
        EXPECT_EQ(std::holds_alternative<std::monostate>(row.into),
                  row.takes == OptionRow::Takes::Help);
    }
}

TEST(OptionTable, NoTwoOptionsShareANameNorADestination) {
    std::map<std::string, std::string> owner;
    std::set<const void*> destinations;
    for (const OptionRow& row : table()) {
        for (const std::string& name : row.spelledNames()) {
            EXPECT_TRUE(owner.emplace(name, row.names).second)
                << name << " in " << row.names << " and " << owner[name];
        }
        if (!std::holds_alternative<std::monostate>(row.into)) {
            const void* address = std::visit(
                [](auto into) -> const void* {
                    if constexpr (std::is_pointer_v<decltype(into)>) {
                        return into;
                    } else {
                        return nullptr;
                    }
                },
                row.into);
            EXPECT_TRUE(destinations.insert(address).second) << row.names;
        }
    }
}

TEST(OptionTable, RtfTwoOptionsKeepTheirNames) {
    // RTF 2.x's runner's options (its --help), each marked as such, with its short form.
    const std::set<std::string> rtf2{
        "-h,-?,--help", "--version",         "-t,--test",   "--tests",          "-s,--suite",
        "--suites",     "-r,--recursive",    "-p,--param",  "-e,--environment", "--repetition",
        "-o,--output",  "--output-type",     "--no-output", "--no-summary",     "-d,--detail",
        "-v,--verbose", "-w,--web-reporter", "--web-port"};
    std::set<std::string> marked;
    for (const OptionRow& row : table()) {
        if (row.fromRtf2) {
            marked.insert(row.names);
        }
    }
    EXPECT_EQ(marked, rtf2);
}

TEST(OptionTable, OnlyParamAndEnvironmentAreFreeText) {
    std::set<std::string> freeText;
    for (const OptionRow& row : table()) {
        if (row.freeText) {
            freeText.insert(row.longName());
        }
    }
    EXPECT_EQ(freeText, (std::set<std::string>{"--param", "--environment"}));
}

TEST(OptionTable, TheManPageAndTheReferenceNameEveryVisibleOption) {
    const std::vector<OptionRow> rows = table();
    const std::string man = manPage(rows, "9.9.9");
    const std::string reference = markdownReference(rows);
    EXPECT_EQ(man.rfind(".\\\"", 0), 0u) << man.substr(0, 80);
    EXPECT_NE(man.find(".TH ROBOTTESTINGFRAMEWORK\\-TESTRUNNER 1"), std::string::npos);
    EXPECT_NE(man.find("9.9.9"), std::string::npos);
    EXPECT_NE(man.find(".SH EXIT STATUS"), std::string::npos);
    for (const OptionRow& row : rows) {
        for (const std::string& name : row.spelledNames()) {
            const bool hidden = row.group.empty();
            EXPECT_EQ(man.find("\\fB" + asRoff(name) + "\\fR") != std::string::npos, !hidden)
                << name;
            EXPECT_EQ(reference.find("`" + name) != std::string::npos, !hidden) << name;
        }
    }
}

TEST(OptionTable, HelpManAndHelpMarkdownPrintThePages) {
    for (const char* flag : {"--help-man", "--help-markdown"}) {
        Options options;
        const char* argv[] = {"robottestingframework-testrunner", flag};
        const ParseResult result = parseOptions(2, argv, options);
        EXPECT_EQ(result.outcome, ParseResult::Outcome::Exit) << flag;
        EXPECT_EQ(result.status, 0) << flag;
        EXPECT_NE(result.text.find("-suite"), std::string::npos) << flag;  // roff: \-\-suite
    }
    // Hidden from --help: they are for the build and the docs.
    Options options;
    const char* argv[] = {"robottestingframework-testrunner", "--help"};
    const ParseResult help = parseOptions(2, argv, options);
    EXPECT_EQ(help.text.find("--help-man"), std::string::npos);
    EXPECT_NE(help.text.find("Tests to run:"), std::string::npos);
}
