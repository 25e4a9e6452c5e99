// A test plug-in that fails one check (and goes on), then passes another.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class FailingTest : public robottestingframework::TestCase {
public:
    FailingTest() : TestCase("FailingTest") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("failing test is running");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(2 + 2 == 5, "two and two make five");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "still going after the failed check");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(FailingTest)
