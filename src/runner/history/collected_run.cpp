#include "runner/history/collected_run.h"

#include <robottestingframework/Measurement.h>

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
            for (const MeasurementRecord& measured : test.measurements) {
                appender.addMeasurement({result.test, measured.name(), measured.value,
                                         measured.unit(), measured.hasLow, measured.low,
                                         measured.hasHigh, measured.high});
            }
        }
    }
}

}  // namespace runner
}  // namespace robottestingframework
