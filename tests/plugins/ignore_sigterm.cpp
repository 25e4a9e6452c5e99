// Ignores SIGTERM and blocks forever: only SIGKILL stops it.
#include <signal.h>
#include <unistd.h>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class IgnoreSigterm : public robottestingframework::TestCase {
public:
    IgnoreSigterm() : TestCase("ignore_sigterm") {}
    void run() override {
        ::signal(SIGTERM, SIG_IGN);
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("SIGTERM is ignored now");
        for (;;) {
            ::pause();
        }
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(IgnoreSigterm)
