// Written the way RTF 2.x test plug-ins are: it must compile and run unchanged.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class Rtf2StyleTest : public TestCase {
public:
    Rtf2StyleTest() : TestCase("Rtf2StyleTest") {}
    virtual ~Rtf2StyleTest() {}

    virtual bool setup(int argc, char** argv) {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("running Rtf2StyleTest::setup...");
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(argc >= 1, "argv[0] is the test's name");
        return true;
    }

    virtual void tearDown() {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("running Rtf2StyleTest::teardown...");
    }

    virtual void run() {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("testing integers");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(2 < 3, "is not smaller");
        int a = 5;
        int b = 3;
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(a > b,
                                         Asserter::format("%d is not bigger than %d.", a, b));
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(getEnvironment() == "--robot icubSim",
                                                 "the suite's environment: " + getEnvironment());
        if (getParam().empty())
            ROBOTTESTINGFRAMEWORK_TEST_REPORT("no param");
        else
            ROBOTTESTINGFRAMEWORK_TEST_REPORT("param: " + getParam());
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(Rtf2StyleTest)
