// Forks a child that sleeps forever, then (with --hang) hangs or (default) passes and leaves the
// child behind. Either way the child must not outlive the run.
#include <unistd.h>

#include <string>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class ForkSleeper : public robottestingframework::TestCase {
public:
    ForkSleeper() : TestCase("fork_sleeper") {}
    void run() override {
        pid_t child = ::fork();
        if (child == 0) {
            for (;;) {
                ::pause();
            }
        }
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("left child " + std::to_string(child) + " behind");
        if (getParam().find("--hang") != std::string::npos) {
            for (;;) {
                ::pause();
            }
        }
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(ForkSleeper)
