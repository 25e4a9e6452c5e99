// A user's program running a test through the library: exit 0 when it passed.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>

class Arithmetic : public robottestingframework::TestCase {
public:
    Arithmetic() : TestCase("Arithmetic") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(6 * 7 == 42, "six times seven"); }
};

int main() {
    Arithmetic test;
    robottestingframework::TestRunner runner;
    runner.addTest(&test);
    robottestingframework::TestResult result;
    robottestingframework::TestResultCollector collector;
    result.addListener(&collector);
    runner.run(result);
    return collector.testCount() == 1 && collector.passedCount() == 1 ? 0 : 1;
}
