// Reports what it was given (param words, environment) and fails when a word it is told to
// expect is missing: "--expect-param WORD", "--expect-env WORD" in its param.
#include <string>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

using robottestingframework::Arguments;

class EchoTest : public robottestingframework::TestCase {
public:
    EchoTest() : TestCase("EchoTest") {}

    bool setup(int argc, char** argv) override {
        std::string words;
        for (int i = 0; i < argc; ++i) {
            words += std::string(i ? " " : "") + "[" + argv[i] + "]";
        }
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("argv " + words);
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("environment [" + getEnvironment() + "]");
        Arguments::getOption(argc, argv, "--expect-param", expectParam_);
        Arguments::getOption(argc, argv, "--expect-env", expectEnv_);
        return true;
    }

    void run() override {
        ++runs_;
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("run number " + std::to_string(runs_));
        if (!expectParam_.empty()) {
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(getParam().find(expectParam_) != std::string::npos,
                                             "param holds " + expectParam_);
        }
        if (!expectEnv_.empty()) {
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(getEnvironment().find(expectEnv_) != std::string::npos,
                                             "environment holds " + expectEnv_);
        }
    }

private:
    std::string expectParam_;
    std::string expectEnv_;
    int runs_ = 0;
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(EchoTest)
