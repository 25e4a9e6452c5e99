// Reports "run K done" at each repetition and dies of SIGSEGV in the one given with
// "--crash-at K" (default 2).
#include <string>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class CrashAtRepetition : public robottestingframework::TestCase {
public:
    CrashAtRepetition() : TestCase("crash_at_repetition") {}

    bool setup(int argc, char** argv) override {
        std::string value;
        if (robottestingframework::Arguments::getOption(argc, argv, "--crash-at", value)) {
            crashAt_ = std::stoi(value);
        }
        return true;
    }

    void run() override {
        ++runs_;
        if (runs_ == crashAt_) {
            volatile int* nowhere = nullptr;
            *nowhere = 1;
        }
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("run " + std::to_string(runs_) + " done");
    }

private:
    int crashAt_ = 2;
    int runs_ = 0;
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(CrashAtRepetition)
