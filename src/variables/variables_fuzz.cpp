// Fuzz target: variable files and ${...} expansion (cmake/Fuzz.cmake, ./run.sh fuzz). The input
// is a --var-file up to its first NUL byte, then a text to expand with its variables; each
// variable's value is expanded too, and escape() must give back what it escaped.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "variables/variables.h"

using namespace robottestingframework::variables;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = input.find('\0');
    std::istringstream file(input.substr(0, nul));
    const std::string text = nul == std::string::npos ? input : input.substr(nul + 1);

    std::vector<Variable> read;
    std::string error;
    if (!readVariables(file, "vars.env", read, error) && error.empty()) {
        __builtin_trap();  // a refused file says why
    }
    VariableTable table;
    table.define({"robot", "icubSim", Source::Suite, "suite.xml:2"});
    table.define({"part", "${robot}/arm", Source::WorldFile, "world.xml:3"});
    for (const auto& variable : read) {
        table.define(variable);
    }
    std::string expanded;
    try {
        expanded = table.expand(text);
    } catch (const ExpandError& e) {
        if (e.message.empty()) {
            __builtin_trap();
        }
    }
    table.closeTo(text.substr(0, 64));
    table.resetTotal();
    for (const auto& variable : table.all()) {
        try {
            table.valueOf(variable.first);
        } catch (const ExpandError&) {
        }
    }
    // Expanding an escaped text gives the text back, whatever it holds.
    table.resetTotal();
    try {
        if (table.expand(escape(text)) != text) {
            __builtin_trap();
        }
    } catch (const ExpandError& e) {
        if (e.kind != ExpandError::Kind::TooLong && e.kind != ExpandError::Kind::TooMuch) {
            __builtin_trap();
        }
    }
    return 0;
}
