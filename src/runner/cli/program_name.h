// The runner's name, which starts every line it says of its own.
#pragma once

namespace robottestingframework {
namespace runner {

constexpr const char* programName = "robottestingframework-testrunner";

}  // namespace runner
}  // namespace robottestingframework
