#include "runner/history/history_run_key.h"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <random>

namespace robottestingframework {
namespace runner {

namespace {

std::string variable(const char* name) {
    const char* value = std::getenv(name);
    return value == nullptr ? std::string() : std::string(value);
}

}  // namespace

std::string historyRunKey() {
    if (!variable("RTF_RUN_ID").empty()) {
        return variable("RTF_RUN_ID");
    }
    // Each names the whole run its shards belong to; a re-run of the pipeline is another run.
    if (!variable("GITHUB_RUN_ID").empty()) {
        return "github:" + variable("GITHUB_RUN_ID") + "." + variable("GITHUB_RUN_ATTEMPT");
    }
    if (!variable("CI_PIPELINE_ID").empty()) {
        return "gitlab:" + variable("CI_PIPELINE_ID");
    }
    if (!variable("BUILD_TAG").empty()) {
        return "jenkins:" + variable("BUILD_TAG");
    }
    if (!variable("BUILDKITE_BUILD_ID").empty()) {
        return "buildkite:" + variable("BUILDKITE_BUILD_ID");
    }
    if (!variable("TEST_INVOCATION_ID").empty()) {
        return "bazel:" + variable("TEST_INVOCATION_ID");
    }
    std::random_device device;
    const auto now = std::chrono::system_clock::now().time_since_epoch().count();
    return "local:" + std::to_string(now) + "." + std::to_string(::getpid()) + "." +
           std::to_string(device());
}

}  // namespace runner
}  // namespace robottestingframework
