// A number a test measured (a tracking error, a loop rate), with its unit and optional limits.
// Recorded as an event of its test (ResultEvent::Kind::Measurement); one outside its limits
// also fails the test (Asserter::testMeasure).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace robottestingframework {

struct Measurement {
    std::string name;
    double value = 0;
    std::string unit;                           // may be empty
    std::optional<double> low = std::nullopt;   // the smallest value that passes, if any
    std::optional<double> high = std::nullopt;  // the largest value that passes, if any

    bool withinLimits() const;
};

// A unit longer than this is an error of the test that gave it.
constexpr std::size_t kMaxMeasurementUnitSize = 64;

// Empty when `measurement` can be recorded; else why not (an empty name, a value or limit
// that is not a finite number, a unit over kMaxMeasurementUnitSize bytes, low above high).
std::string measurementProblem(const Measurement& measurement);

// "joint error = 0.12 rad, outside [0, 0.05] rad": what a failed measurement says.
std::string outOfLimitsMessage(const Measurement& measurement);

// "joint error = 0.01 rad (limits [0, 0.05] rad)": the measurement event's message, for
// listeners that show only messages.
std::string describeMeasurement(const Measurement& measurement);

// The shortest text that reads back as the same double ("0.1", "1e-07", "42").
std::string formatNumber(double value);

// "[0, 0.05]", "[>= 0]", "[<= 0.05]"; empty without limits.
std::string limitsText(const Measurement& measurement);

}  // namespace robottestingframework
