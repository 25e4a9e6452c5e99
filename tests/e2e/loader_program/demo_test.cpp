// An RTF 2.x test plug-in (examples/plugin).
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class DemoTest : public TestCase {
public:
    DemoTest() : TestCase("DemoTest") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("demo test runs");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(2 < 3, "2 is smaller than 3");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(DemoTest)
