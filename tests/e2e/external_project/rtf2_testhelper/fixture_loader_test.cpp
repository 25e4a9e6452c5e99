// Loads the fixture plug-in named by its param with DllFixturePluginLoader, as RTF 2.x's own
// fixture test does: the suite is its dispatcher as soon as it is added, its setup gets
// "MY_FIXTURE_TEST_PARAM --x 1" as argv, and a collapse reported from its tearDown reaches the
// suite.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>
#include <robottestingframework/dll/DllFixturePluginLoader.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;
using namespace robottestingframework::plugin;

class Smaller : public TestCase {
public:
    Smaller() : TestCase("Smaller") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(3 < 5, "smaller"); }
};

class RecordingSuite : public TestSuite {
public:
    RecordingSuite() : TestSuite("RecordingSuite") {}
    void fixtureCollapsed(TestMessage reason) override { collapse = reason.getMessage(); }
    std::string collapse;
};

class FixtureLoader : public TestCase {
public:
    FixtureLoader() : TestCase("FixtureLoader") {}

    bool setup(int argc, char** argv) override {
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(argc >= 2, "missing the fixture's file name");
        fixtureFile_ = argv[1];
        return true;
    }

    void run() override {
        DllFixturePluginLoader loader;
        FixtureManager* fixture = loader.open(fixtureFile_);
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_FALSE(fixture != nullptr, loader.getLastError());

        RecordingSuite suite;
        Smaller test;
        suite.addFixtureManager(fixture);
        suite.addTest(&test);
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(fixture->getDispatcher() == &suite,
                                         "the suite is the dispatcher once added");
        fixture->setParam("MY_FIXTURE_TEST_PARAM --collapse-in-teardown");

        TestResultCollector collector;
        TestResult result;
        result.addListener(&collector);
        TestRunner runner;
        runner.addTest(&suite);
        runner.run(result);

        ROBOTTESTINGFRAMEWORK_TEST_CHECK(suite.collapse == "collapsed in tearDown",
                                         "the collapse reached the suite");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.testCount() == 1, "test count");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.passedCount() == 1,
                                         "the fixture's setup accepted its argv");
    }

private:
    std::string fixtureFile_;
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(FixtureLoader)
