// A plug-in whose verdict is its param, for the CTest helper tests (tests/ctest):
//   --verdict pass|fail      the test passes only with "pass" (no param: it fails)
//   --environment-is TEXT    and only when the suite/runner environment is exactly TEXT
#include <string>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

using robottestingframework::Arguments;
using robottestingframework::TestCase;

class VerdictTest : public TestCase {
public:
    VerdictTest() : TestCase("ctest_verdict") {}

    bool setup(int argc, char** argv) override {
        Arguments::getOption(argc, argv, "--verdict", verdict_);
        checkEnvironment_ = Arguments::getOption(argc, argv, "--environment-is", environment_);
        return true;
    }

    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("verdict: " + verdict_);
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(verdict_ == "pass", "the param asks this test to pass");
        if (checkEnvironment_)
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(getEnvironment() == environment_,
                                             "environment is '" + getEnvironment() + "'");
    }

private:
    std::string verdict_;
    std::string environment_;
    bool checkEnvironment_ = false;
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(VerdictTest)
