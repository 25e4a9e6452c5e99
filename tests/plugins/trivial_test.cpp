// The cheapest possible passing test: for the isolation benchmark.
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class TrivialTest : public robottestingframework::TestCase {
public:
    TrivialTest() : TestCase("trivial_test") {}
    void run() override {}
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(TrivialTest)
