// The benchmark's test: does nothing but pass, so a run measures the framework alone.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class TrivialTest : public robottestingframework::TestCase {
public:
    TrivialTest() : TestCase("trivial") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "nothing to do"); }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(TrivialTest)
