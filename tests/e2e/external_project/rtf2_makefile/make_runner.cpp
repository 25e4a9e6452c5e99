// A program built by a Makefile (-lrobottestingframework): RTF 2.x's simple_runner way.
#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>

using namespace robottestingframework;

class Arithmetic : public TestCase {
public:
    Arithmetic() : TestCase("Arithmetic") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(6 * 7 == 42, "six times seven"); }
};

int main() {
    ConsoleListener console(false);
    TestResultCollector collector;
    TestResult result;
    result.addListener(&console);
    result.addListener(&collector);
    Arithmetic test;
    TestSuite suite("MakeSuite");
    suite.addTest(&test);
    TestRunner runner;
    runner.addTest(&suite);
    runner.run(result);
    return collector.passedCount() == 1 && collector.failedCount() == 0 ? 0 : 1;
}
