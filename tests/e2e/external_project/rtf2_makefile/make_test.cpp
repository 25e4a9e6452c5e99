// A test plug-in built by a Makefile (-lrobottestingframework -lrobottestingframework-dll).
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class MakeTest : public robottestingframework::TestCase {
public:
    MakeTest() : TestCase("MakeTest") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("built by make");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(getParam() != "--fail", "the param is not --fail");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(MakeTest)
