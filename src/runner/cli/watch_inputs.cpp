// What --watch watches and the command line of each watched run (watch_command.h).
#include <cstring>
#include <set>

#include "runner/cli/watch_command.h"

namespace robottestingframework {
namespace runner {

std::vector<std::string> watchedFiles(const std::vector<SuiteSpec>& suites) {
    std::vector<std::string> files;
    std::set<std::string> seen;
    auto add = [&](const std::string& file) {
        if (!file.empty() && seen.insert(file).second) {
            files.push_back(file);
        }
    };
    for (const auto& suite : suites) {
        add(suite.where.file.str());
        for (const auto& test : suite.tests) {
            add(test.where.file.str());  // a <test file="..."> is read from its own file
            add(test.path.str());
        }
        for (const auto& fixture : suite.fixtures) {
            add(fixture.path.str());
        }
    }
    return files;
}

std::vector<std::string> watchedRunArguments(int argc, char** argv, const std::string& report) {
    std::vector<std::string> words;
    bool outputs = false;
    for (int i = 0; i < argc; ++i) {
        const char* word = argv[i];
        if (std::strcmp(word, "--watch") == 0) {
            continue;
        }
        outputs = outputs ||
                  (i > 0 &&
                   (std::strcmp(word, "-o") == 0 || std::strncmp(word, "--output=", 9) == 0 ||
                    std::strcmp(word, "--output") == 0 || std::strcmp(word, "--no-output") == 0));
        words.emplace_back(word);
    }
    if (!report.empty()) {
        if (!outputs) {
            words.insert(words.end(), {"--output", "result.txt"});
        }
        words.insert(words.end(), {"--output", "junit:" + report});
    }
    return words;
}

}  // namespace runner
}  // namespace robottestingframework
