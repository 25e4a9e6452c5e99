// Fuzz target: a --rerun-failed report (JUnit or CTRF JSON) through parseFailedTests, then the
// suites cut down to what it names (cmake/Fuzz.cmake, ./run.sh fuzz).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "runner/reports/rerun_report.h"

using namespace robottestingframework;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<runner::FailedTest> failed;
    try {
        failed = runner::parseFailedTests(text, "report.xml");
    } catch (const std::runtime_error& e) {
        if (std::string(e.what()).find("report.xml") == std::string::npos) {
            __builtin_trap();  // every error names the report
        }
        return 0;
    }
    std::vector<runner::SuiteSpec> suites(2);
    suites[0].name = "arm";
    suites[1].name = "";
    for (auto& suite : suites) {
        for (const char* name : {"reach", "grasp", ""}) {
            runner::TestSpec test;
            test.name = name;
            test.plugin = "libarm.so";
            test.depends = {"reach"};
            suite.tests.push_back(test);
        }
    }
    runner::keepFailedTests(suites, failed);
    for (const auto& suite : suites) {
        if (suite.tests.empty()) {
            __builtin_trap();  // only suites left with a test are kept
        }
    }
    return 0;
}
