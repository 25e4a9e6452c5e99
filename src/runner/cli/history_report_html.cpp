#include "runner/cli/history_report_html.h"

#include <algorithm>
#include <cstdio>

#include "core/text_safety.h"
#include "runner/history/history_trends.h"

namespace robottestingframework {
namespace runner {

namespace {

constexpr std::size_t listed = 10;

std::string text(const std::string& raw) {
    return reporters::escapeMarkup(reporters::visibleText(raw), reporters::Markup::Quoted);
}

std::string number(const char* pattern, double value) {
    char out[64];
    std::snprintf(out, sizeof(out), pattern, value);
    return out;
}

std::string stateClass(const std::string& state) {
    if (state == "passed" || state == "skipped" || state == "flaky") {
        return state;
    }
    return state == "interrupted" ? "other" : "failed";
}

// One square a run, oldest first, coloured by its outcome, its time in its tooltip.
std::string outcomes(const TestHistory& history) {
    std::string out = "<span class=\"runs\">";
    for (std::size_t i = 0; i < history.runs.size(); ++i) {
        const TestHistoryEntry& entry = history.runs[i];
        out += "<span class=\"run " + stateClass(entry.state) + "\" title=\"run " +
               std::to_string(i + 1) + ": " + text(entry.state) + ", " +
               number("%.3f s", entry.duration) + "\"></span>";
    }
    return out + "</span>";
}

// A polyline of `values` in a 120 x 24 box, scaled to their range.
std::string sparkline(const std::vector<double>& values, const std::string& cls) {
    if (values.empty()) {
        return "";
    }
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    const double span = *high - *low > 0 ? *high - *low : 1;
    std::string points;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double x = values.size() == 1 ? 60 : 2 + 116.0 * i / (values.size() - 1);
        const double y = 22 - 20 * (values[i] - *low) / span;
        points += number("%.1f", x) + "," + number("%.1f", y) + " ";
    }
    return "<svg class=\"" + cls + "\" width=\"120\" height=\"24\" viewBox=\"0 0 120 24\">" +
           "<polyline points=\"" + points + "\"/></svg>";
}

std::vector<double> durations(const TestHistory& history) {
    std::vector<double> values;
    for (const TestHistoryEntry& entry : history.runs) {
        if (entry.state != "skipped") {
            values.push_back(entry.duration);
        }
    }
    return values;
}

const char* const style = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5rem; color: #1f2328; }
table { border-collapse: collapse; margin: .5rem 0 1.5rem; }
th, td { border-bottom: 1px solid #d0d7de; padding: .25rem .6rem; text-align: left; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.runs { display: inline-flex; gap: 1px; }
.run { display: inline-block; width: 8px; height: 14px; background: #8c959f; }
.run.passed { background: #1a7f37; } .run.failed { background: #cf222e; }
.run.flaky { background: #bf8700; } .run.skipped { background: #d0d7de; }
svg polyline { fill: none; stroke: #0969da; stroke-width: 1.5; }
.none { color: #656d76; }
)";

}  // namespace

std::string historyReportHtml(const std::vector<TestHistory>& histories,
                              const RecentMeasurements& measurements, std::size_t runs,
                              unsigned int asked) {
    std::string out =
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        "<title>Test history</title><style>" +
        std::string(style) + "</style></head><body>\n<h1>Test history</h1>\n<p id=\"scope\">" +
        std::to_string(histories.size()) + " tests in the last " + std::to_string(runs) + " runs" +
        (runs < asked ? " (of " + std::to_string(asked) + " asked)" : "") + "</p>\n";

    out += "<h2>Always failing</h2>\n";
    const auto failing = alwaysFailingTests(histories);
    if (failing.empty()) {
        out += "<p class=\"none\" id=\"always-failing\">none</p>\n";
    } else {
        out += "<ul id=\"always-failing\">";
        for (const TestHistory* history : failing) {
            out += "<li data-test=\"" + text(history->test) + "\">" + text(history->test) + " (" +
                   std::to_string(history->runs.size()) + " runs)</li>";
        }
        out += "</ul>\n";
    }

    out +=
        "<h2>Slowed down</h2>\n<p>The median of the newest third of runs against the older "
        "runs', beyond the noise floor: the largest of " +
        number("%.1f s", absoluteNoiseSeconds) + ", " + number("%.0f", relativeNoise * 100) +
        " % of the older median and 3 times the older runs' median deviation.</p>\n";
    const auto slowed = mostSlowedTests(histories, listed);
    if (slowed.empty()) {
        out += "<p class=\"none\" id=\"slowed\">none</p>\n";
    } else {
        out +=
            "<table id=\"slowed\"><tr><th>test</th><th>before</th><th>recent</th>"
            "<th>ratio</th><th>noise floor</th></tr>";
        for (const SlowedTest& test : slowed) {
            out += "<tr data-test=\"" + text(test.history->test) + "\"><td>" +
                   text(test.history->test) + "</td><td class=\"num\">" +
                   number("%.3f s", test.slowdown.before) + "</td><td class=\"num\">" +
                   number("%.3f s", test.slowdown.recent) + "</td><td class=\"num\">" +
                   number("%.2fx", test.slowdown.ratio()) + "</td><td class=\"num\">" +
                   number("%.3f s", test.slowdown.noise) + "</td></tr>";
        }
        out += "</table>\n";
    }

    out += "<h2>Slowest</h2>\n<ol id=\"slowest\">";
    for (const TestHistory* history : slowestByMedian(histories, listed)) {
        out += "<li data-test=\"" + text(history->test) + "\">" + text(history->test) + ": " +
               number("%.3f s", medianSeconds(*history)) + " median</li>";
    }
    out += "</ol>\n";

    out +=
        "<h2>Every test</h2>\n<table id=\"tests\"><tr><th>test</th><th>outcomes, oldest "
        "first</th><th>flaky rate</th><th>median</th><th>durations</th></tr>";
    for (const TestHistory& history : histories) {
        const double rate = flakyRate(history);
        out += "<tr class=\"test\" data-test=\"" + text(history.test) + "\" data-flaky=\"" +
               number("%.3f", rate) + "\"" + (alwaysFails(history) ? " data-always-fails" : "") +
               "><td>" + text(history.test) + "</td><td>" + outcomes(history) +
               "</td><td class=\"num\">" + number("%.1f %%", 100 * rate) +
               "</td><td class=\"num\">" + number("%.3f s", medianSeconds(history)) + "</td><td>" +
               sparkline(durations(history), "durations") + "</td></tr>";
    }
    out += "</table>\n";

    out += "<h2>Measurements</h2>\n";
    if (measurements.byTest.empty()) {
        out += "<p class=\"none\" id=\"measurements\">none</p>\n";
    } else {
        out +=
            "<table id=\"measurements\"><tr><th>test</th><th>measurement</th><th>latest</th>"
            "<th>over the runs</th></tr>";
        for (const auto& [test, values] : measurements.byTest) {
            std::vector<std::string> names;
            for (const MeasuredValue& value : values) {
                if (std::find(names.begin(), names.end(), value.name) == names.end()) {
                    names.push_back(value.name);
                }
            }
            for (const std::string& name : names) {
                std::vector<double> series;
                std::string unit;
                for (const MeasuredValue& value : values) {
                    if (value.name == name) {
                        series.push_back(value.value);
                        unit = value.unit;
                    }
                }
                out += "<tr class=\"measurement\" data-test=\"" + text(test) + "\" data-name=\"" +
                       text(name) + "\" data-values=\"" + std::to_string(series.size()) +
                       "\"><td>" + text(test) + "</td><td>" + text(name) +
                       "</td><td class=\"num\">" + number("%g", series.back()) +
                       (unit.empty() ? "" : " " + text(unit)) + "</td><td>" +
                       sparkline(series, "values") + "</td></tr>";
            }
        }
        out += "</table>\n";
    }
    return out + "</body></html>\n";
}

}  // namespace runner
}  // namespace robottestingframework
