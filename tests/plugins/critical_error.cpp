// Raises a critical error: the rest of its suite makes no sense.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class CriticalError : public robottestingframework::TestCase {
public:
    CriticalError() : TestCase("critical_error") {}
    void run() override { ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL("the robot is not powered"); }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(CriticalError)
