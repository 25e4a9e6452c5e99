// Reports something, prints something, then dereferences a null pointer (SIGSEGV).
#include <cstdio>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class CrashSegv : public robottestingframework::TestCase {
public:
    CrashSegv() : TestCase("crash_segv") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("about to dereference a null pointer");
        std::printf("last words before the crash\n");
        volatile int* nowhere = nullptr;
        *nowhere = 42;
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(CrashSegv)
