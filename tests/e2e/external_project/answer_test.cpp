// A user's test plug-in: passes when its param says --answer 42.
#include <string>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class AnswerTest : public robottestingframework::TestCase {
public:
    AnswerTest() : TestCase("AnswerTest") {}

    bool setup(int argc, char** argv) override {
        return robottestingframework::Arguments::getOption(argc, argv, "--answer", answer_);
    }

    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(answer_ == "42", "the answer"); }

private:
    std::string answer_;
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(AnswerTest)
