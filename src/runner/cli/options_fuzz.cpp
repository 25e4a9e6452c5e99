// Fuzz target: the command line through parseOptions, the input split into arguments at each
// NUL byte, then the selection it gives (--tag, --exclude-tag, --filter) matched against a few
// tests (cmake/Fuzz.cmake, ./run.sh fuzz). parseOptions never exits nor prints.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "runner/cli/options.h"
#include "runner/model/suite_model.h"
#include "runner/plan/selection.h"

using namespace robottestingframework;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> words{"robottestingframework-testrunner"};
    std::string word;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            words.push_back(word);
            word.clear();
        } else {
            word += static_cast<char>(data[i]);
        }
    }
    words.push_back(word);
    std::vector<const char*> argv;
    for (const auto& arg : words) {
        argv.push_back(arg.c_str());
    }
    argv.push_back(nullptr);

    runner::Options options;
    runner::ParseResult result =
        runner::parseOptions(static_cast<int>(words.size()), argv.data(), options);
    if (result.outcome == runner::ParseResult::Outcome::Exit) {
        if (result.text.empty() || (result.status != 0 && result.status != 2)) {
            __builtin_trap();  // an exit says why, with status 0 or 2
        }
        return 0;
    }
    std::vector<runner::SuiteSpec> suites(2);
    suites[0].name = "arm";
    suites[1].name = "a suite with a long name ****";
    const std::vector<std::vector<std::string>> tags = {{}, {"arm", "slow"}, {"leg"}};
    for (auto& suite : suites) {
        for (const auto& tagged : tags) {
            runner::TestSpec test;
            test.name = "reach" + std::to_string(suite.tests.size());
            test.plugin = "libarm.so";
            test.tags = tagged;
            suite.tests.push_back(test);
        }
    }
    runner::applySelection(suites, options.selection);
    return 0;
}
