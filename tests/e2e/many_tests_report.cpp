// Writes the HTML report of a run of N in-process tests (every 100th fails, each prints a line;
// one prints more than the page keeps): the page the 10 000-test browser check opens.
// Usage: rtf-many-tests-report N FILE
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestSuite.h>

#include "reporters/html_reporter.h"

using namespace robottestingframework;

namespace {

class NumberedTest : public TestCase {
public:
    NumberedTest(int number, TestResult& result)
        : TestCase("test " + std::to_string(number)), number_(number), result_(result) {}
    void run() override {
        std::string printed = "line of test " + std::to_string(number_) + "\n";
        if (number_ == 1) {
            printed = std::string(2 * reporters::HtmlReporter::outputCap, 'x') + "\n";
        }
        result_.addOutput(this, printed);
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(number_ % 100 != 0, "not a multiple of 100");
    }

private:
    int number_;
    TestResult& result_;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s N FILE\n", argv[0]);
        return 2;
    }
    const int count = std::atoi(argv[1]);
    TestResult result;
    TestResultCollector collector;
    collector.setKeepEventLog(false);
    result.addListener(&collector);
    TestSuite suite("many");
    std::vector<std::unique_ptr<NumberedTest>> tests;
    for (int i = 1; i <= count; ++i) {
        tests.push_back(std::make_unique<NumberedTest>(i, result));
        suite.addTest(tests.back().get());
    }
    result.startTestRunner();
    suite.run(result);
    result.endTestRunner();
    TestMessage error;
    if (!reporters::HtmlReporter(collector, reporters::ReporterSettings{}).write(argv[2], &error)) {
        std::fprintf(stderr, "%s\n", error.toString().c_str());
        return 1;
    }
    return 0;
}
