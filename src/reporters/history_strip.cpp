#include "reporters/history_strip.h"

#include <cstdio>

#include <robottestingframework/Measurement.h>

#include "core/text_safety.h"

namespace robottestingframework {
namespace reporters {

namespace {

template <typename Number, typename Format>
std::string list(const std::vector<Number>& values, Format format) {
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        out += (i == 0 ? "" : ",") + format(values[i]);
    }
    return out + "]";
}

std::string trendData(const MeasurementTrend& trend) {
    const auto whole = [](auto n) { return std::to_string(n); };
    std::string out =
        "{\"name\":" + jsonString(trend.name) + ",\"unit\":" + jsonString(trend.unit) +
        ",\"values\":" + list(trend.values, formatNumber) +
        ",\"ago\":" + list(trend.runsAgo, whole) + ",\"outside\":" + list(trend.outside, whole);
    if (trend.low) {
        out += ",\"low\":" + formatNumber(*trend.low);
    }
    if (trend.high) {
        out += ",\"high\":" + formatNumber(*trend.high);
    }
    return out + "}";
}

}  // namespace

std::string historyStripData(const HistoryStrip& strip) {
    std::string out = "{\"states\":[";
    for (std::size_t i = 0; i < strip.states.size(); ++i) {
        out += (i == 0 ? "" : ",") + jsonString(strip.states[i]);
    }
    out += "],\"durations\":[";
    char number[32];
    for (std::size_t i = 0; i < strip.durations.size(); ++i) {
        std::snprintf(number, sizeof(number), "%.6f", strip.durations[i]);
        out += (i == 0 ? "" : ",") + std::string(number);
    }
    std::snprintf(number, sizeof(number), "%.4f", strip.flakyRate);
    out += "],\"flakyRate\":" + std::string(number);
    if (!strip.measurements.empty()) {
        out += ",\"measurements\":" + list(strip.measurements, trendData);
    }
    return out + "}";
}

}  // namespace reporters
}  // namespace robottestingframework
