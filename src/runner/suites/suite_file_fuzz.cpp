// Fuzz target: a suite file's text through parseSuite (cmake/Fuzz.cmake, ./run.sh fuzz). A
// malformed suite is a SuiteFileError naming the file and line; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "runner/suites/suite_file.h"

using namespace robottestingframework;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    // A folder that does not exist: plug-ins and test files named relatively are not found.
    const std::string path = "/nonexistent/rtf-fuzz/suite.xml";
    const std::vector<variables::Variable> commandLine = {
        {"robot", "icubSim", variables::Source::CommandLine, "--var"},
        {"speed", "${robot}-30", variables::Source::VarFile, "vars.env:1"}};
    std::vector<std::string> warnings;
    try {
        runner::SuiteSpec suite = runner::parseSuite(text, path, warnings, commandLine);
        if (suite.name.empty()) {
            __builtin_trap();  // a suite always has a name (the file's stem at worst)
        }
    } catch (const runner::SuiteFileError& e) {
        if (std::string(e.what()).compare(0, path.size() + 1, path + ":") != 0) {
            __builtin_trap();  // every error names the file
        }
    }
    return 0;
}
