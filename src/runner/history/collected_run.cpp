#include "runner/history/collected_run.h"

namespace robottestingframework {
namespace runner {

std::string historyTestId(const SuiteRecord& suite, const TestRecord& test) {
    const std::string& name = test.reportName();
    return suite.name.empty() ? name : suite.name + "/" + name;
}

void appendCollectedRun(RunAppender& appender, const TestResultCollector& collector) {
    for (const SuiteRecord& suite : collector.suites()) {
        appender.addSuite({suite.name, suite.duration});
        for (const TestRecord& test : suite.tests) {
            HistoryTestResult result;
            result.test = historyTestId(suite, test);
            result.suite = suite.name;
            result.state = toString(test.status);
            result.duration = test.duration;
            result.attempts = static_cast<unsigned int>(test.attempts.size() + 1);
            appender.addTest(result);
            // Measurements (issue 22 item 2) go here: for each of test.events that is a
            // measurement, appender.addMeasurement({result.test, name, value, unit, limits}).
        }
    }
}

}  // namespace runner
}  // namespace robottestingframework
