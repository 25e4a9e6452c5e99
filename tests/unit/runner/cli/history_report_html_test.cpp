// The history report's HTML page: every test with its outcomes, the lists, measurements, and
// test ids that look like HTML kept as text.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runner/cli/history_report_html.h"

using namespace robottestingframework::runner;

namespace {

TestHistory history(const std::string& id, const std::vector<std::string>& states,
                    const std::vector<double>& seconds) {
    TestHistory made;
    made.test = id;
    for (std::size_t i = 0; i < states.size(); ++i) {
        made.runs.push_back({states[i], seconds[i], 1});
    }
    return made;
}

std::size_t count(const std::string& text, const std::string& part) {
    std::size_t found = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
        ++found;
    }
    return found;
}

}  // namespace

TEST(HistoryReportHtml, ShowsEachTestTheListsAndTheMeasurements) {
    const std::vector<TestHistory> histories = {
        history("robot/<b>arm</b>", {"failed", "failed", "failed"}, {1, 1, 1}),
        history("robot/drive", {"passed", "passed", "passed", "passed", "passed", "passed"},
                {1, 1, 1, 1, 2, 2}),
    };
    RecentMeasurements measured;
    measured.runs = 2;
    measured.byTest["robot/drive"] = {{0, "speed", 1.5, "m/s", {}, {}},
                                      {1, "speed", 1.7, "m/s", {}, {}}};
    const std::string page = historyReportHtml(histories, measured, 6, 30);
    EXPECT_NE(page.find("2 tests in the last 6 runs (of 30 asked)"), std::string::npos);
    EXPECT_EQ(page.find("<b>arm"), std::string::npos);  // text, not markup
    EXPECT_NE(page.find("<ul id=\"always-failing\"><li data-test=\"robot/&lt;b&gt;arm"),
              std::string::npos)
        << page;
    EXPECT_NE(page.find("<table id=\"slowed\">"), std::string::npos);
    EXPECT_NE(page.find("<tr data-test=\"robot/drive\"><td>robot/drive</td>"), std::string::npos);
    EXPECT_EQ(count(page, "<tr class=\"test\""), 2u);
    EXPECT_EQ(count(page, "class=\"run failed\""), 3u);
    EXPECT_EQ(count(page, "class=\"run passed\""), 6u);
    EXPECT_NE(page.find("data-name=\"speed\" data-values=\"2\""), std::string::npos);
    EXPECT_NE(page.find("1.7 m/s"), std::string::npos);
    EXPECT_EQ(page.find("<script"), std::string::npos);
}

TEST(HistoryReportHtml, AnEmptyHistorySaysNone) {
    const std::string page = historyReportHtml({}, RecentMeasurements(), 0, 30);
    EXPECT_NE(page.find("<p class=\"none\" id=\"always-failing\">none</p>"), std::string::npos);
    EXPECT_NE(page.find("<p class=\"none\" id=\"measurements\">none</p>"), std::string::npos);
}
