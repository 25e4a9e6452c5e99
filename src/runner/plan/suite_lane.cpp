#include "runner/plan/suite_lane.h"

namespace robottestingframework {
namespace runner {

void SuiteLane::open(std::vector<std::string> environment,
                     std::shared_ptr<const platform::PrivateNetwork> network) {
    std::unique_ptr<TestExecutor> lane = base_.makeLane();
    if (lane) {
        if (auto* holder = dynamic_cast<WorkerEnvironment*>(lane.get())) {
            holder->setWorkerEnvironment(std::move(environment));
        }
        if (auto* holder = dynamic_cast<WorkerNetwork*>(lane.get())) {
            holder->setWorkerNetwork(std::move(network));
        }
    }
    std::lock_guard<std::mutex> lock(mutex_);
    own_ = std::move(lane);
}

void SuiteLane::close() {
    std::unique_ptr<TestExecutor> done;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        done = std::move(own_);
    }
}

TestExecutor& SuiteLane::current() {
    std::lock_guard<std::mutex> lock(mutex_);
    return own_ ? *own_ : base_;
}

void SuiteLane::interrupt() {
    std::lock_guard<std::mutex> lock(mutex_);
    (own_ ? *own_ : base_).interrupt();
}

}  // namespace runner
}  // namespace robottestingframework
