// Waits for `--seconds N` (default 30), or until it is interrupted (a fixture collapse stops the
// running test), then passes. For tests that need a test in progress while the world changes.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class WaitingTest : public robottestingframework::TestCase {
public:
    WaitingTest() : TestCase("WaitingTest") {}

    bool setup(int argc, char** argv) override {
        std::string value;
        if (robottestingframework::Arguments::getOption(argc, argv, "--seconds", value)) {
            seconds_ = std::stod(value);
        }
        return true;
    }

    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("waiting");
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait_for(lock, std::chrono::duration<double>(seconds_),
                       [this] { return interrupted_; });
    }

    void interrupt() override {
        TestCase::interrupt();
        std::lock_guard<std::mutex> lock(mutex_);
        interrupted_ = true;
        wake_.notify_all();
    }

private:
    double seconds_ = 30;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool interrupted_ = false;
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(WaitingTest)
