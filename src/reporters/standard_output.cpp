#include "reporters/standard_output.h"

namespace robottestingframework {
namespace reporters {

bool namesStandardOutput(const std::string& filename) {
    return filename == "-" || filename == "/dev/stdout";
}

}  // namespace reporters
}  // namespace robottestingframework
