// The key that makes the shards of one run one run in the history: RTF_RUN_ID when set, else
// the CI engine's id of the pipeline or workflow run (GitHub Actions, GitLab CI, Jenkins,
// Buildkite, Bazel's invocation), else one made for this process alone.
#pragma once

#include <string>

namespace robottestingframework {
namespace runner {

std::string historyRunKey();

}  // namespace runner
}  // namespace robottestingframework
