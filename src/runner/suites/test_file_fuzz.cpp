// Fuzz target: a test file's text (<test file="..."/>) through parseTestFile, with the suite's
// variables defined (cmake/Fuzz.cmake, ./run.sh fuzz).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "runner/suites/suite_file.h"

using namespace robottestingframework;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string path = "/nonexistent/rtf-fuzz/tests/arm.xml";
    const std::vector<variables::Variable> suite = {
        {"robot", "icubSim", variables::Source::Suite, "suite.xml:2"},
        {"part", "${robot}/left_arm", variables::Source::Suite, "suite.xml:3"}};
    std::vector<std::string> warnings;
    try {
        runner::parseTestFile(text, path, warnings, suite);
    } catch (const runner::SuiteFileError& e) {
        if (std::string(e.what()).compare(0, path.size() + 1, path + ":") != 0) {
            __builtin_trap();  // every error names the file
        }
    }
    return 0;
}
