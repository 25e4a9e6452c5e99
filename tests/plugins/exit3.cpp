// Calls exit(3) in the middle of its run.
#include <cstdlib>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class Exit3 : public robottestingframework::TestCase {
public:
    Exit3() : TestCase("exit3") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("about to exit with status 3");
        std::exit(3);
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(Exit3)
