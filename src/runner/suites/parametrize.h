// Parametrized tests (docs/how-to/parametrized-tests.md): a <test> with <parametrize name="speed">
// 10, 20</parametrize> children runs once per value, ${speed} standing for it in the test's
// plug-in and attributes; several <parametrize> make a matrix (every combination), as pytest's
// stacked parametrize and Avocado's variants do. Each instance is an ordinary test of the suite
// with an id of its own ("t.py[--speed 10]"), so --filter, -k, reruns, shards and history see it.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace robottestingframework {
namespace runner {

// The most instances one parametrized <test> makes: past it a typo (an axis of thousands of
// values) would make a suite no one meant.
constexpr std::size_t maxParametrizedInstances = 10000;

// One <parametrize>: a name and its values, in the order written.
struct ParameterAxis {
    std::string name;
    std::vector<std::string> values;
};

// One instance: a value for each axis, in the axes' order.
using ParameterInstance = std::vector<std::pair<std::string, std::string>>;

// The values of a <parametrize>: separated by commas, each trimmed, empty ones dropped.
std::vector<std::string> parameterValues(const std::string& text);

// Every combination of the axes' values, the first axis changing slowest (nested loops in the
// order written). Empty when an axis has no value.
std::vector<ParameterInstance> instancesOf(const std::vector<ParameterAxis>& axes);

// `text` with each ${NAME} of an axis of `instance` replaced by its value; any other ${...} is
// left for the suite's variables.
std::string substituteAxes(const std::string& text, const ParameterInstance& instance);

// Whether `text` names an axis of `instance` as ${NAME}.
bool usesAxis(const std::string& text, const ParameterInstance& instance);

// The part in [] of each instance's id: its param on one line when every instance's param is
// different and not empty (as a plug-in given twice with two params is today: "[--speed 10]"),
// else its values "speed=10,mode=fast".
std::vector<std::string> instanceLabels(const std::vector<std::string>& params,
                                        const std::vector<ParameterInstance>& instances);

}  // namespace runner
}  // namespace robottestingframework
