// A fixture manager that sets up fine, then reports a collapse from a thread of its own, and
// with --die-after-setup instead exits (status 7) shortly after setup.
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class FixtureCollapse : public robottestingframework::FixtureManager {
public:
    bool setup(int /*argc*/, char** /*argv*/) override {
        ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("world is up");
        bool die = getParam().find("--die-after-setup") != std::string::npos;
        watcher_ = std::thread([this, die] {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            if (die) {
                ::_exit(7);
            }
            getDispatcher()->fixtureCollapsed(
                robottestingframework::TestMessage("the simulator fell over"));
        });
        return true;
    }
    void tearDown() override {
        if (watcher_.joinable()) {
            watcher_.join();
        }
    }
    ~FixtureCollapse() override {
        if (watcher_.joinable()) {
            watcher_.detach();
        }
    }

private:
    std::thread watcher_;
};

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(FixtureCollapse)
