// Blocks forever in a system call (pause()), after a report.
#include <unistd.h>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class HangBlock : public robottestingframework::TestCase {
public:
    HangBlock() : TestCase("hang_block") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("waiting for a message that never comes");
        for (;;) {
            ::pause();
        }
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(HangBlock)
