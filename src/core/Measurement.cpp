#include <robottestingframework/Measurement.h>

#include <charconv>
#include <cmath>

namespace robottestingframework {

bool Measurement::withinLimits() const {
    return (!low || value >= *low) && (!high || value <= *high);
}

std::string formatNumber(double value) {
    char text[64];
    const auto result = std::to_chars(text, text + sizeof(text), value);
    return std::string(text, result.ptr);
}

std::string limitsText(const Measurement& measurement) {
    if (measurement.low && measurement.high) {
        return "[" + formatNumber(*measurement.low) + ", " + formatNumber(*measurement.high) + "]";
    }
    if (measurement.low) {
        return "[>= " + formatNumber(*measurement.low) + "]";
    }
    if (measurement.high) {
        return "[<= " + formatNumber(*measurement.high) + "]";
    }
    return std::string();
}

std::string measurementProblem(const Measurement& measurement) {
    const std::string what = "measurement '" + measurement.name + "'";
    if (measurement.name.empty()) {
        return "a measurement needs a name (it was given an empty one)";
    }
    if (!std::isfinite(measurement.value)) {
        return what + ": the value " + formatNumber(measurement.value) + " is not a finite number";
    }
    if (measurement.unit.size() > kMaxMeasurementUnitSize) {
        return what + ": the unit is " + std::to_string(measurement.unit.size()) +
               " bytes long, more than " + std::to_string(kMaxMeasurementUnitSize);
    }
    if ((measurement.low && !std::isfinite(*measurement.low)) ||
        (measurement.high && !std::isfinite(*measurement.high))) {
        return what + ": its limits " + limitsText(measurement) + " are not finite numbers";
    }
    if (measurement.low && measurement.high && *measurement.low > *measurement.high) {
        return what + ": its low limit " + formatNumber(*measurement.low) +
               " is above its high limit " + formatNumber(*measurement.high);
    }
    return std::string();
}

std::string describeMeasurement(const Measurement& measurement) {
    const std::string unit = measurement.unit.empty() ? std::string() : " " + measurement.unit;
    const std::string limits = limitsText(measurement);
    return measurement.name + " = " + formatNumber(measurement.value) + unit +
           (limits.empty() ? std::string() : " (limits " + limits + unit + ")");
}

std::string outOfLimitsMessage(const Measurement& measurement) {
    const std::string unit = measurement.unit.empty() ? std::string() : " " + measurement.unit;
    return "measurement '" + measurement.name + "' = " + formatNumber(measurement.value) + unit +
           ", outside its limits " + limitsText(measurement) + unit;
}

}  // namespace robottestingframework
