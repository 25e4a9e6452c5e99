// A fixture manager that reports, then crashes (SIGSEGV) in setup.
#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class FixtureCrashSetup : public robottestingframework::FixtureManager {
public:
    bool setup(int /*argc*/, char** /*argv*/) override {
        ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("starting the simulator");
        volatile int* nowhere = nullptr;
        *nowhere = 1;
        return true;
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(FixtureCrashSetup)
