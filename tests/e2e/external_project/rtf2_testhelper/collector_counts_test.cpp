// The collector's counts as RTF 2.x gave them: two suites, the first one's fixture throws in
// its setup; that suite's test is not run and not counted.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class Smaller : public TestCase {
public:
    Smaller() : TestCase("Smaller") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(3 < 5, "smaller"); }
};

class BrokenWorld : public FixtureManager {
public:
    explicit BrokenWorld(FixtureEvents* dispatcher) : FixtureManager(dispatcher) {}
    bool setup(int, char**) override {
        throw FixtureException(TestMessage("the world cannot be set up"));
    }
};

class FineWorld : public FixtureManager {
public:
    explicit FineWorld(FixtureEvents* dispatcher) : FixtureManager(dispatcher) {}
    bool setup(int, char**) override { return true; }
};

class CollectorCounts : public TestCase {
public:
    CollectorCounts() : TestCase("CollectorCounts") {}

    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(getParam().empty(), "the param is empty");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(getEnvironment().empty(), "the environment is empty");

        TestResultCollector collector;
        TestResult result;
        result.addListener(&collector);
        Smaller test;
        TestSuite first("FirstSuite");
        BrokenWorld broken(&first);
        first.addFixtureManager(&broken);
        first.addTest(&test);
        TestSuite second("SecondSuite");
        FineWorld fine(&second);
        second.addFixtureManager(&fine);
        second.addTest(&test);
        TestRunner runner;
        runner.addTest(&first);
        runner.addTest(&second);
        runner.run(result);

        ROBOTTESTINGFRAMEWORK_TEST_REPORT(Asserter::format(
            "suites %zu (passed %zu, failed %zu), tests %zu (passed %zu, failed %zu)",
            collector.suiteCount(), collector.passedSuiteCount(), collector.failedSuiteCount(),
            collector.testCount(), collector.passedCount(), collector.failedCount()));
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.suiteCount() == 2, "suite count");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.passedSuiteCount() == 1, "passed suites");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.failedSuiteCount() == 1, "failed suites");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.testCount() == 1, "test count");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.passedCount() == 1, "passed tests");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.failedCount() == 0, "failed tests");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(CollectorCounts)
