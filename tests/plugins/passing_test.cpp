// A test plug-in that passes: one report, one check that holds.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class PassingTest : public robottestingframework::TestCase {
public:
    PassingTest() : TestCase("PassingTest") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("passing test is running");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(1 + 1 == 2, "arithmetic holds");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(PassingTest)
