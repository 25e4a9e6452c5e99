// Passes when the environment is what "--expect-env VALUE" in its param says (empty when the
// option has no value); without that option, when the param is empty.
#include <robottestingframework/Arguments.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class EnvironmentTest : public TestCase {
public:
    EnvironmentTest() : TestCase("EnvironmentTest") {}

    bool setup(int argc, char** argv) override {
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(argc >= 1 && getName() == argv[0],
                                                    "argv[0] is the test's name");
        expectEnv_ = Arguments::getOption(argc, argv, "--expect-env", expected_);
        return true;
    }

    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("param [" + getParam() + "] environment [" +
                                          getEnvironment() + "]");
        if (expectEnv_) {
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(getEnvironment() == expected_,
                                             "the environment is [" + expected_ + "]");
        } else {
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(getParam().empty(), "the param is empty");
        }
    }

private:
    bool expectEnv_ = false;
    std::string expected_;
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(EnvironmentTest)
