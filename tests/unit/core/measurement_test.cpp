// A measurement's checks: what passes its limits, what cannot be recorded, and what the
// messages say; and what Asserter::testMeasure sends for each.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <robottestingframework/Measurement.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>

#include "core_test_helpers.h"

using namespace robottestingframework;

namespace {

Measurement measured(double value, std::optional<double> low = {}, std::optional<double> high = {},
                     std::string unit = "rad") {
    return Measurement{"tracking error", value, std::move(unit), low, high};
}

}  // namespace

TEST(Measurement, WithinClosedLimitsIncludingTheBounds) {
    EXPECT_TRUE(measured(0.0, 0.0, 0.05).withinLimits());
    EXPECT_TRUE(measured(0.05, 0.0, 0.05).withinLimits());
    EXPECT_FALSE(measured(0.0500001, 0.0, 0.05).withinLimits());
    EXPECT_FALSE(measured(-1e-9, 0.0, 0.05).withinLimits());
}

TEST(Measurement, OneSidedAndNoLimits) {
    EXPECT_TRUE(measured(1e300).withinLimits());
    EXPECT_TRUE(measured(100, 95.0).withinLimits());
    EXPECT_FALSE(measured(90, 95.0).withinLimits());
    EXPECT_FALSE(measured(110, std::nullopt, 105.0).withinLimits());
}

TEST(Measurement, OutOfLimitsMessageNamesValueLimitsAndUnit) {
    EXPECT_EQ(outOfLimitsMessage(measured(0.12, 0.0, 0.05)),
              "measurement 'tracking error' = 0.12 rad, outside its limits [0, 0.05] rad");
    EXPECT_EQ(outOfLimitsMessage(measured(3, std::nullopt, 2.5, "")),
              "measurement 'tracking error' = 3, outside its limits [<= 2.5]");
}

TEST(Measurement, NumbersReadBackExactly) {
    EXPECT_EQ(formatNumber(0.1), "0.1");
    EXPECT_EQ(formatNumber(42), "42");
    EXPECT_EQ(std::stod(formatNumber(1.0 / 3)), 1.0 / 3);
}

TEST(Measurement, RefusesNonFiniteValuesEmptyNamesLongUnitsAndCrossedLimits) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(measurementProblem(measured(0.01, 0.0, 0.05)), "");
    EXPECT_NE(measurementProblem(measured(std::nan(""))).find("not a finite number"),
              std::string::npos);
    EXPECT_NE(measurementProblem(measured(inf)).find("not a finite number"), std::string::npos);
    EXPECT_NE(measurementProblem(Measurement{"", 1, "", {}, {}}).find("empty"), std::string::npos);
    EXPECT_EQ(measurementProblem(measured(1, {}, {}, std::string(64, 'u'))), "");
    EXPECT_NE(measurementProblem(measured(1, {}, {}, std::string(65, 'u'))).find("65 bytes"),
              std::string::npos);
    EXPECT_NE(measurementProblem(measured(1, 2.0, 1.0)).find("above its high limit"),
              std::string::npos);
    EXPECT_NE(measurementProblem(measured(1, -inf, 1.0)).find("not finite"), std::string::npos);
}

namespace {

// The kinds of a test's events after `body` ran as the test, and its state.
struct Outcome {
    std::vector<ResultEvent::Kind> kinds;
    TestStatus status;
};

Outcome runBody(std::function<void()> body) {
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    rtf_test::LambdaTest test("t", std::move(body));
    test.run(result);
    Outcome outcome{{}, collector.suites().at(0).tests.at(0).status};
    std::vector<ResultEvent> scratch;
    for (const ResultEvent& event : collector.suites().at(0).tests.at(0).eventsInOrder(scratch)) {
        outcome.kinds.push_back(event.kind);
    }
    return outcome;
}

}  // namespace

TEST(Measurement, InsideLimitsIsOneMeasurementEventAndPasses) {
    const Outcome o =
        runBody([] { ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN("e", 0.01, "rad", 0, 0.05); });
    EXPECT_EQ(o.kinds, std::vector<ResultEvent::Kind>{ResultEvent::Kind::Measurement});
    EXPECT_EQ(o.status, TestStatus::Passed);
}

TEST(Measurement, OutsideLimitsIsTheMeasurementThenAFailureAndTheTestGoesOn) {
    const Outcome o = runBody([] {
        ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN("e", 0.5, "rad", 0, 0.05);
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("after");
    });
    EXPECT_EQ(o.kinds, (std::vector<ResultEvent::Kind>{ResultEvent::Kind::Measurement,
                                                       ResultEvent::Kind::Failure,
                                                       ResultEvent::Kind::Report}));
    EXPECT_EQ(o.status, TestStatus::Failed);
}

TEST(Measurement, ABadValueIsAnErrorOfTheTestAndNoMeasurement) {
    const Outcome o = runBody([] { ROBOTTESTINGFRAMEWORK_TEST_MEASURE("e", std::nan(""), "rad"); });
    EXPECT_EQ(o.kinds, std::vector<ResultEvent::Kind>{ResultEvent::Kind::Error});
    EXPECT_EQ(o.status, TestStatus::Error);
}
