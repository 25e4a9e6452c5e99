// A user's program showing its run on two live web pages (WebProgressListener, RTF_web): exit 0
// when both served the page and saw the test pass.
#include <cstdio>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/WebProgressListener.h>

class Arithmetic : public robottestingframework::TestCase {
public:
    Arithmetic() : TestCase("Arithmetic") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(6 * 7 == 42, "six times seven"); }
};

int main() {
    robottestingframework::WebProgressListener first(0);
    robottestingframework::WebProgressListener second(0);
    if (!first.isListening() || !second.isListening() || first.port() == second.port()) {
        std::fprintf(stderr, "not served: %s %s\n", first.error().c_str(), second.error().c_str());
        return 1;
    }
    std::printf("%s %s\n", first.url().c_str(), second.url().c_str());
    Arithmetic test;
    robottestingframework::TestRunner runner;
    runner.addTest(&test);
    robottestingframework::TestResult result;
    robottestingframework::TestResultCollector collector;
    result.addListener(&collector);
    result.addListener(&first);
    result.addListener(&second);
    runner.run(result);
    return collector.passedCount() == 1 ? 0 : 1;
}
