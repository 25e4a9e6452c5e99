// Runs and checks fine, then aborts (SIGABRT) in tearDown.
#include <cstdlib>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class CrashInTeardown : public robottestingframework::TestCase {
public:
    CrashInTeardown() : TestCase("crash_in_teardown") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "ran fine"); }
    void tearDown() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("tearing down");
        std::abort();
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(CrashInTeardown)
