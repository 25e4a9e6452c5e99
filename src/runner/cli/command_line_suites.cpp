#include "runner/cli/command_line_suites.h"

#include <robottestingframework/dll/DllPluginLoader.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "languages/test_loader.h"
#include "runner/cli/plugin_file_kind.h"
#include "runner/model/test_id.h"
#include "runner/suites/suite_file.h"

namespace robottestingframework {
namespace runner {

namespace fs = std::filesystem;

const char* const commandLineSuiteName = "tests";

namespace {

bool hidden(const fs::path& path) {
    std::string name = path.filename().string();
    return !name.empty() && name[0] == '.';
}

bool isSuiteFile(const std::string& path) {
    return fs::path(path).extension() == ".xml";
}

// The name of the root element of the XML file at `path`, read from its first 64 KiB past the
// declaration, comments, processing instructions and a DOCTYPE; empty when none is found.
std::string rootElementOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string text(64 * 1024, '\0');
    in.read(&text[0], static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    std::size_t at = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (at < text.size()) {
        at = text.find('<', at);
        if (at == std::string::npos || at + 1 >= text.size()) {
            return {};
        }
        const char next = text[at + 1];
        if (next == '?') {
            at = text.find("?>", at);
        } else if (text.compare(at, 4, "<!--") == 0) {
            at = text.find("-->", at);
        } else if (next == '!') {
            at = text.find('>', at);  // a DOCTYPE (without an internal subset)
        } else {
            const std::size_t end = text.find_first_of(" \t\r\n/>", at + 1);
            return text.substr(at + 1, end == std::string::npos ? end : end - at - 1);
        }
        if (at == std::string::npos) {
            return {};
        }
        ++at;
    }
    return {};
}

// An XML file of a --suites folder that is not a suite but another file this runner reads or
// writes beside suites: a world file of the process fixture, a JUnit report (-o junit:...).
// Such files are passed over; any other root element is read as a suite (and is an error
// naming the file when it is not one).
bool isOtherRunnerFile(const std::string& path) {
    const std::string root = rootElementOf(path);
    return root == "world" || root == "testsuites" || root == "testsuite";
}

// The suite files of a --suites folder: its XML files but those of the formats above (passed
// over quietly) and those whose root element is not a suite's: a robot's configuration, a
// middleware's XML beside the suites. RTF 2.x passed those over; they are passed over with a
// warning naming the root element, so a misspelt <suite> is seen. A file without a root
// element (malformed) is kept: reading it says what is wrong, exit 2.
std::vector<std::string> suitesOfFolder(const std::vector<std::string>& files,
                                        std::vector<std::string>& warnings) {
    std::vector<std::string> suites;
    for (const auto& file : files) {
        if (isOtherRunnerFile(file)) {
            continue;
        }
        const std::string root = rootElementOf(file);
        if (!root.empty() && root != "suite" && root != "suit") {
            warnings.push_back(file + ": warning: the root element is <" + root +
                               ">, not <suite>: passed over (--suite " + file +
                               " reads it as a suite)");
            continue;
        }
        suites.push_back(file);
    }
    return suites;
}

bool isTestFile(const std::string& path) {
    return !languages::typeFromFile(path).empty();
}

// The files of a --tests folder that run as tests. A shared library there that is not a test
// plug-in (a fixture plug-in, or a library the build put beside the plug-ins) is passed over
// with a warning, as RTF 2.x passed it over; named with --test it is still a failed test.
std::vector<std::string> testsOfFolder(const std::vector<std::string>& files,
                                       std::vector<std::string>& warnings) {
    std::vector<std::string> tests;
    for (const auto& file : files) {
        if (languages::typeFromFile(file) == "dll") {
            const PluginFileKind kind = pluginFileKind(file);
            if (kind == PluginFileKind::Fixture) {
                warnings.push_back(file +
                                   ": warning: a fixture plug-in, not a test: passed over "
                                   "(a suite file's <fixture> names it)");
                continue;
            }
            if (kind == PluginFileKind::Other) {
                warnings.push_back(file +
                                   ": warning: not a test plug-in (no "
                                   "ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN in it): passed over");
                continue;
            }
        }
        tests.push_back(file);
    }
    return tests;
}

TestSpec commandLineTest(const std::string& file) {
    TestSpec test;
    test.plugin = file;
    // Bare names are looked for in the current folder first, as next to a suite file.
    test.path = plugin::findPlugin(file, ".");
    test.repetition = 0;
    test.where = SourceLocation{"", 0};
    return test;
}

}  // namespace

std::vector<std::string> listFolder(const std::string& folder, bool recursive,
                                    bool (*keep)(const std::string& path)) {
    std::error_code error;
    if (!fs::is_directory(folder, error)) {
        throw std::runtime_error(folder + ": not a folder");
    }
    std::vector<std::string> files;
    auto consider = [&](const fs::directory_entry& entry) {
        if (!hidden(entry.path()) && entry.is_regular_file(error) && keep(entry.path().string())) {
            files.push_back(entry.path().string());
        }
    };
    if (recursive) {
        fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied,
                                            error);
        for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
            if (it->is_directory() && hidden(it->path())) {
                it.disable_recursion_pending();
                continue;
            }
            consider(*it);
        }
    } else {
        fs::directory_iterator it(folder, error);
        for (; !error && it != fs::directory_iterator(); it.increment(error)) {
            consider(*it);
        }
    }
    if (error) {
        throw std::runtime_error(folder + ": cannot list the folder (" + error.message() + ")");
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<variables::Variable> commandLineVariables(const Options& options) {
    std::vector<variables::Variable> found;
    for (const auto& file : options.variableFiles) {
        std::string error;
        if (!variables::readVariableFile(file, found, error)) {
            throw std::runtime_error("--var-file " + error);
        }
    }
    for (const auto& variable : options.variables) {
        found.push_back({variable.first, variable.second, variables::Source::CommandLine, "--var"});
    }
    return found;
}

std::vector<SuiteSpec> readSources(const Options& options, std::vector<std::string>& warnings) {
    std::vector<SuiteSpec> suites;
    // First: a bad --var-file is an error even when no suite reads it.
    const std::vector<variables::Variable> variables = commandLineVariables(options);

    SuiteSpec commandLine;
    commandLine.name = commandLineSuiteName;
    for (const auto& file : options.tests) {
        commandLine.tests.push_back(commandLineTest(file));
    }
    for (const auto& folder : options.testDirs) {
        auto files = testsOfFolder(listFolder(folder, options.recursive, isTestFile), warnings);
        if (files.empty()) {
            warnings.push_back(folder + ": warning: no test files in this folder");
        }
        for (const auto& file : files) {
            commandLine.tests.push_back(commandLineTest(file));
        }
    }
    if (!commandLine.tests.empty()) {
        // Paths given on the command line start from the current folder.
        assignTestIds(commandLine, ".");
        suites.push_back(std::move(commandLine));
    }

    std::vector<std::string> suiteFiles = options.suites;
    for (const auto& folder : options.suiteDirs) {
        auto files = suitesOfFolder(listFolder(folder, options.recursive, isSuiteFile), warnings);
        if (files.empty()) {
            warnings.push_back(folder + ": warning: no suite files (*.xml) in this folder");
        }
        suiteFiles.insert(suiteFiles.end(), files.begin(), files.end());
    }
    for (const auto& file : suiteFiles) {
        suites.push_back(readSuiteFile(file, warnings, variables));
    }
    const std::string sameIds = makeIdsUniqueAcrossSuites(suites);
    if (!sameIds.empty()) {
        throw std::runtime_error(sameIds);
    }
    return suites;
}

}  // namespace runner
}  // namespace robottestingframework
