#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "platform/fd_passing.h"
#include "platform/local_socket.h"
#include "platform/private_network.h"
#include "runner/cli/kept_world.h"
#include "runner/cli/world_protocol.h"

namespace robottestingframework {
namespace runner {

namespace {

constexpr int kWatchMs = 250;  // how often a running suite asks the keeper about its world

bool askStatus(const std::string& folder, WorldStatus& status,
               std::vector<platform::FileDescriptor>& fds, std::string& error) {
    std::string why;
    platform::FileDescriptor socket = platform::connectLocal(folder, "keeper.sock", why);
    if (!socket.valid()) {
        error = "no world keeper answers at " + folder + " (" + why +
                "); start one with --world-up " + folder;
        return false;
    }
    std::string packet;
    if (!platform::sendWithFds(socket.get(), worldRequestText(WorldRequest::Status), {}) ||
        !platform::receiveWithFds(socket.get(), packet, fds)) {
        error = "the world keeper at " + folder + " did not answer (it is ending)";
        return false;
    }
    if (!parseWorldStatus(packet, status) || fds.size() != status.networkDescriptors) {
        error = "the world keeper at " + folder +
                " answered what this runner does not read (another version?)";
        return false;
    }
    return true;
}

// Why a world that is not up cannot serve tests; empty when it is up.
std::string notUp(const WorldStatus& status) {
    switch (status.state) {
        case WorldStatus::State::Up:
            return "";
        case WorldStatus::State::Starting:
            return "the world is still being set up";
        case WorldStatus::State::Collapsed:
            return "the world collapsed: " + status.reason;
        case WorldStatus::State::Stopping:
            return "the world is being torn down" +
                   (status.reason.empty() ? std::string() : " (" + status.reason + ")");
    }
    return "";
}

class WorldStandIn : public FixtureManager {
public:
    explicit WorldStandIn(std::string folder) : folder_(std::move(folder)) {
        setName("world kept at " + folder_);
    }
    ~WorldStandIn() override { stopWatching(); }

    bool setup(int, char**) override {
        const std::string why = ask();
        if (!why.empty()) {
            throw std::runtime_error(why);
        }
        stopWatching();
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = false;
        }
        watcher_ = std::thread([this] { watch(); });
        return true;
    }

    bool check() override {
        const std::string why = ask();
        if (why.empty()) {
            return true;
        }
        if (FixtureEvents* dispatcher = getDispatcher()) {
            dispatcher->fixtureCollapsed(TestMessage(why));
        }
        return false;
    }

    void tearDown() override { stopWatching(); }

private:
    // Empty when the world is up, else why not.
    std::string ask() {
        WorldStatus status;
        std::vector<platform::FileDescriptor> fds;
        std::string error;
        if (!askStatus(folder_, status, fds, error)) {
            return error;
        }
        return notUp(status);
    }

    void watch() {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!stop_) {
            changed_.wait_for(lock, std::chrono::milliseconds(kWatchMs));
            if (stop_) {
                break;
            }
            lock.unlock();
            const std::string why = ask();
            if (!why.empty()) {
                if (FixtureEvents* dispatcher = getDispatcher()) {
                    dispatcher->fixtureCollapsed(TestMessage(why));
                }
                return;
            }
            lock.lock();
        }
    }

    void stopWatching() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        changed_.notify_all();
        if (watcher_.joinable()) {
            watcher_.join();
        }
    }

    std::string folder_;
    std::mutex mutex_;
    std::condition_variable changed_;
    bool stop_ = false;
    std::thread watcher_;
};

}  // namespace

bool joinKeptWorld(const std::string& folder, const std::string& suite, KeptWorld& world,
                   std::string& error) {
    WorldStatus status;
    std::vector<platform::FileDescriptor> fds;
    if (!askStatus(folder, status, fds, error)) {
        return false;
    }
    // A keeper of shared worlds (discover_tests) holds them for every suite that needs them.
    if (status.suite != suite && status.suite.rfind(sharedWorldKeeperPrefix, 0) != 0) {
        error = "the world keeper at " + folder + " keeps the world of suite " + status.suite +
                ", not of suite " + suite + " (give --world-up and --world the same suite)";
        return false;
    }
    if (fds.size() == 2) {
        world.network =
            std::make_shared<const platform::PrivateNetwork>(std::move(fds[0]), std::move(fds[1]));
    } else if (fds.size() == 1) {
        world.network = std::make_shared<const platform::PrivateNetwork>(platform::FileDescriptor(),
                                                                         std::move(fds[0]));
    }
    world.fixture = std::make_unique<WorldStandIn>(folder);
    return true;
}

}  // namespace runner
}  // namespace robottestingframework
