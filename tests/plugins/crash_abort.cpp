// Calls abort() (SIGABRT) after a report.
#include <cstdlib>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class CrashAbort : public robottestingframework::TestCase {
public:
    CrashAbort() : TestCase("crash_abort") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("about to abort");
        std::abort();
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(CrashAbort)
