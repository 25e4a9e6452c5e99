#include "runner/cli/history_report_command.h"

#include <cstdio>
#include <fstream>

#include "core/text_safety.h"
#include "runner/cli/exit_status.h"
#include "runner/cli/history_report_html.h"
#include "runner/cli/program_name.h"
#include "runner/history/history_database.h"
#include "runner/history/history_error.h"
#include "runner/history/history_queries.h"
#include "runner/history/history_trends.h"

namespace robottestingframework {
namespace runner {

namespace {

constexpr std::size_t listed = 10;

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
    char text[128];
    std::snprintf(text, sizeof(text), pattern, a, b, c);
    return text;
}

}  // namespace

std::string historyReportText(const std::vector<TestHistory>& histories, std::size_t runs,
                              unsigned int asked) {
    std::string out = "History: " + std::to_string(histories.size()) + " tests in the last " +
                      std::to_string(runs) + " runs" +
                      (runs < asked ? " (of " + std::to_string(asked) + " asked)" : "") + "\n";
    out += "\nFlakiest tests (runs flaky or changing outcome):\n";
    const auto flaky = flakiestTests(histories, listed);
    if (flaky.empty()) {
        out += "  none\n";
    }
    for (const FlakyTest& test : flaky) {
        out += format("  %5.1f %%  ", 100 * test.rate) +
               reporters::visibleText(test.history->test) + "  (" +
               std::to_string(test.history->runs.size()) + " runs)\n";
    }
    out += "\nTests that failed every run:\n";
    const auto failing = alwaysFailingTests(histories);
    if (failing.empty()) {
        out += "  none\n";
    }
    for (const TestHistory* history : failing) {
        out += "  " + reporters::visibleText(history->test) + "  (" +
               std::to_string(history->runs.size()) + " runs)\n";
    }
    out +=
        "\nMost slowed-down tests (median of the newest third of runs against the older, "
        "beyond the noise floor):\n";
    const auto slowed = mostSlowedTests(histories, listed);
    if (slowed.empty()) {
        out += "  none\n";
    }
    for (const SlowedTest& test : slowed) {
        out += format("  %5.2fx  %.3f s -> %.3f s  ", test.slowdown.ratio(), test.slowdown.before,
                      test.slowdown.recent) +
               reporters::visibleText(test.history->test) +
               format("  (noise floor %.3f s)", test.slowdown.noise) + "\n";
    }
    return out;
}

int historyReportCommand(const Options& options) {
    try {
        HistoryDatabase database(options.history, HistoryDatabase::Mode::Read);
        const std::size_t runs = std::min<std::size_t>(countRuns(database), options.historyRuns);
        const std::vector<TestHistory> histories = recentHistories(database, options.historyRuns);
        const std::string text = historyReportText(histories, runs, options.historyRuns);
        if (!options.historyHtml.empty()) {
            const std::string page = historyReportHtml(
                histories, recentMeasurements(database, options.historyRuns, nullptr), runs,
                options.historyRuns);
            std::ofstream file(options.historyHtml, std::ios::binary);
            if (!(file << page) || !file.flush()) {
                std::fprintf(stderr, "%s: --history-html: cannot write %s\n", programName,
                             options.historyHtml.c_str());
                return configurationError;
            }
        }
        std::fputs(text.c_str(), stdout);
        return allPassed;
    } catch (const HistoryError& e) {
        std::fprintf(stderr, "%s: %s\n", programName, e.what());
        return configurationError;
    }
}

}  // namespace runner
}  // namespace robottestingframework
