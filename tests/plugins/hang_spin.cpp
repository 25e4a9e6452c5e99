// Spins on the CPU forever, never making a system call.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class HangSpin : public robottestingframework::TestCase {
public:
    HangSpin() : TestCase("hang_spin") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("spinning");
        volatile unsigned long counter = 0;
        for (;;) {
            counter = counter + 1;
        }
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(HangSpin)
