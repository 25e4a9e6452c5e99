#include "runner/cli/run_facts.h"

#include <filesystem>
#include <system_error>

#include "reporters/host_name.h"

namespace robottestingframework {
namespace runner {

namespace {

// An argument as a shell would need it written: quoted when it holds anything but plain
// characters, so the line can be pasted back.
std::string shellWord(const std::string& word) {
    const bool plain = !word.empty() && word.find_first_not_of(
                                            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                            "0123456789-_./=:,+@%") == std::string::npos;
    if (plain) {
        return word;
    }
    std::string quoted = "'";
    for (const char c : word) {
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return quoted + "'";
}

}  // namespace

std::vector<std::pair<std::string, std::string>> runFacts(const Options& options) {
    std::vector<std::pair<std::string, std::string>> facts;
    std::string line;
    for (const std::string& word : options.commandLine) {
        line += (line.empty() ? "" : " ") + shellWord(word);
    }
    facts.emplace_back("command line", line);
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::current_path(error);
    if (!error) {
        facts.emplace_back("working folder", folder.string());
    }
    facts.emplace_back("host", reporters::hostName());
    facts.emplace_back("version", RTF_VERSION);
    facts.emplace_back("isolation",
                       options.isolation == Isolation::None ? "none (in process)" : "process");
    facts.emplace_back("jobs", std::to_string(options.jobs));
    for (const auto& file : options.variableFiles) {
        facts.emplace_back("variable file", file);
    }
    for (const auto& variable : options.variables) {
        facts.emplace_back("variable " + variable.first, variable.second);
    }
    return facts;
}

void addTestFacts(const SuiteSpec& suite, std::map<std::string, reporters::TestFacts>& facts) {
    for (const TestSpec& test : suite.tests) {
        facts[suite.name + "/" + test.id] = {test.type, test.plugin, test.param, test.tags};
    }
}

}  // namespace runner
}  // namespace robottestingframework
