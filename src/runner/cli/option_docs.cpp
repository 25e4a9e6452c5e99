#include "runner/cli/option_docs.h"

#include <algorithm>

namespace robottestingframework {
namespace runner {

namespace {

const char* const program = "robottestingframework-testrunner";

// The groups in the order of their first row; hidden rows (no group) left out.
std::vector<std::string> groupsOf(const std::vector<OptionRow>& rows) {
    std::vector<std::string> groups;
    for (const OptionRow& row : rows) {
        if (!row.group.empty() && row.takes != OptionRow::Takes::Arguments &&
            std::find(groups.begin(), groups.end(), row.group) == groups.end()) {
            groups.push_back(row.group);
        }
    }
    return groups;
}

// Text for roff: backslashes and dashes escaped, no line starting a request.
std::string roff(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\\') {
            out += "\\e";
        } else if (c == '-') {
            out += "\\-";
        } else {
            out += c;
        }
    }
    if (!out.empty() && (out.front() == '.' || out.front() == '\'')) {
        out.insert(0, "\\&");
    }
    return out;
}

// Text for Markdown: the characters that would start emphasis, a tag or a table cell escaped.
std::string markdown(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\\' || c == '*' || c == '_' || c == '|' || c == '<' || c == '>' || c == '`') {
            out += '\\';
        }
        out += c;
    }
    return out;
}

// What the value's rule expects, after the help: " (N: from 1 to 1000000000)".
std::string ruleOf(const OptionRow& row) {
    return row.rule.expected.empty() ? "" : " (" + row.value + ": " + row.rule.expected + ")";
}

std::string valueOf(const OptionRow& row) {
    if (row.value.empty()) {
        return {};
    }
    return row.takes == OptionRow::Takes::MaybeOne ? "[" + row.value + "]" : row.value;
}

}  // namespace

std::string manPage(const std::vector<OptionRow>& rows, const std::string& version) {
    std::string page;
    page += ".\\\" Made by " + std::string(program) +
            " --help-man from its option table (src/runner/cli/option_table.cpp).\n";
    page += ".TH ROBOTTESTINGFRAMEWORK\\-TESTRUNNER 1 \"\" \"" + roff(program) + " " +
            roff(version) + "\" \"User Commands\"\n";
    page += ".SH NAME\n" + roff(program) + " \\- " + roff(programSummary) + "\n";
    page += ".SH SYNOPSIS\n.B " + roff(program) + "\n[\\fIOPTIONS\\fR] [\\fIREPORT\\fR...]\n";
    page += ".SH DESCRIPTION\n" + roff(programSummary) +
            " The options of RTF 2.x's runner keep their names and meaning.\n";
    for (const std::string& group : groupsOf(rows)) {
        page += ".SS " + roff(group) + "\n";
        for (const OptionRow& row : rows) {
            if (row.group != group || row.takes == OptionRow::Takes::Arguments) {
                continue;
            }
            page += ".TP\n";
            const std::vector<std::string> names = row.spelledNames();
            for (std::size_t i = 0; i < names.size(); ++i) {
                page += (i > 0 ? ", " : "") + std::string("\\fB") + roff(names[i]) + "\\fR";
            }
            if (!row.value.empty()) {
                page += " \\fI" + roff(valueOf(row)) + "\\fR";
            }
            page += "\n" + roff(row.help + ruleOf(row)) + (row.fromRtf2 ? " (RTF 2.x)" : "") + "\n";
        }
    }
    for (const OptionRow& row : rows) {
        if (row.takes == OptionRow::Takes::Arguments) {
            page +=
                ".SS Arguments\n.TP\n\\fI" + roff(row.value) + "\\fR...\n" + roff(row.help) + "\n";
        }
    }
    page += ".SH EXIT STATUS\n" + roff(exitStatusHelp) + "\n";
    page +=
        ".SH SEE ALSO\nThe command-line reference, docs/reference/command-line.md, and the "
        "documentation of Robot Testing Framework, docs/index.md (./run.sh docs builds it as "
        "HTML).\n";
    return page;
}

std::string markdownReference(const std::vector<OptionRow>& rows) {
    std::string page;
    page += "<!-- Made by `" + std::string(program) +
            " --help-markdown` from src/runner/cli/option_table.cpp: do not edit; regenerate "
            "with `build/bin/" +
            program + " --help-markdown > docs/reference/command-line.md`. -->\n";
    page += "# Command line\n\n";
    page += "`" + std::string(program) + " [OPTIONS] [REPORT...]`\n\n";
    page += markdown(programSummary) +
            " The options marked RTF 2.x are those of RTF 2.x's runner, with the same names and "
            "meaning. `--name=value` is the same as `--name value`. The same text is in "
            "`--help` and in the man page, `man " +
            std::string(program) + "`.\n";
    for (const std::string& group : groupsOf(rows)) {
        page += "\n## " + group + "\n\n| Option | What it does |\n| --- | --- |\n";
        for (const OptionRow& row : rows) {
            if (row.group != group || row.takes == OptionRow::Takes::Arguments) {
                continue;
            }
            const std::vector<std::string> names = row.spelledNames();
            std::string cell;
            for (std::size_t i = 0; i < names.size(); ++i) {
                cell += (i > 0 ? ", " : "") + ("`" + names[i]) +
                        (i + 1 == names.size() && !row.value.empty() ? " " + valueOf(row) : "") +
                        "`";
            }
            page += "| " + cell + " | " + markdown(row.help + ruleOf(row)) +
                    (row.fromRtf2 ? " *RTF 2.x.*" : "") + " |\n";
        }
    }
    for (const OptionRow& row : rows) {
        if (row.takes == OptionRow::Takes::Arguments) {
            page += "\n## Arguments\n\n`" + row.value + "...`: " + markdown(row.help) + ".\n";
        }
    }
    page += "\n## Exit status\n\n" + markdown(exitStatusHelp) + "\n";
    return page;
}

}  // namespace runner
}  // namespace robottestingframework
