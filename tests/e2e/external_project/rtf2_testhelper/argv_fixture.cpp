// A fixture written for RTF 2.x: its setup reads argv as RTF 2.x gave it, the param's words with
// the first one in argv[0] and no program name. "--collapse-in-teardown" makes its tearDown
// report a collapse through its dispatcher, which RTF 2.x's own fixture test does.
#include <cstdio>
#include <cstring>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class ArgvFixture : public FixtureManager {
public:
    bool setup(int argc, char** argv) override {
        std::printf("argv fixture: argc %d, argv[0] %s\n", argc, argc > 0 ? argv[0] : "(none)");
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(argc >= 1, "missing MY_FIXTURE_TEST_PARAM");
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(
            std::strcmp(argv[0], "MY_FIXTURE_TEST_PARAM") == 0,
            "argv[0] is not MY_FIXTURE_TEST_PARAM");
        collapseInTearDown_ = false;
        for (int i = 1; i < argc; ++i) {
            collapseInTearDown_ |= std::strcmp(argv[i], "--collapse-in-teardown") == 0;
        }
        return true;
    }

    void tearDown() override {
        if (collapseInTearDown_) {
            getDispatcher()->fixtureCollapsed(TestMessage("collapsed in tearDown"));
        }
    }

private:
    bool collapseInTearDown_ = false;
};

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(ArgvFixture)
