// Throws std::runtime_error with a message the report must carry.
#include <stdexcept>

#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class ThrowRuntime : public robottestingframework::TestCase {
public:
    ThrowRuntime() : TestCase("throw_runtime") {}
    void run() override { throw std::runtime_error("the motor driver is on fire"); }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(ThrowRuntime)
