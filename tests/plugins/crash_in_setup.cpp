// Crashes (SIGSEGV) in setup, after a report.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class CrashInSetup : public robottestingframework::TestCase {
public:
    CrashInSetup() : TestCase("crash_in_setup") {}
    bool setup(int /*argc*/, char** /*argv*/) override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("setting up");
        volatile int* nowhere = nullptr;
        *nowhere = 1;
        return true;
    }
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_REPORT("never here"); }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(CrashInSetup)
