// Throws an int: not a std::exception, nothing to ask what() of.
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class ThrowInt : public robottestingframework::TestCase {
public:
    ThrowInt() : TestCase("throw_int") {}
    void run() override { throw 42; }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(ThrowInt)
