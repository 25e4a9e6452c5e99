// An RTF 2.x test that includes only TestAssert.h, TestResultCollector.h and dll/Plugin.h, and
// uses TestResult, TestCase and the collector's reset() the way RTF 2.x's headers allowed.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class Rtf2InnerTest : public TestCase {
public:
    Rtf2InnerTest() : TestCase("inner") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(1 + 1 == 2, "arithmetic"); }
};

class Rtf2CollectorTest : public TestCase {
public:
    Rtf2CollectorTest() : TestCase("Rtf2CollectorTest") {}

    void run() override {
        // A result and collector of its own, as RTF 2.x tests that run sub-tests make them.
        TestResult result;
        TestResultCollector collector;
        result.addListener(&collector);
        Rtf2InnerTest inner;
        static_cast<Test&>(inner).run(result);  // run() hides run(TestResult&), as in RTF 2.x
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.testCount() == 1, "the inner test was counted");
        collector.reset();
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(collector.testCount() == 0, "reset() forgot it");
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("rtf2 collector test ran its inner test");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(Rtf2CollectorTest)
