#include "reporters/reporter.h"

#include "reporters/atomic_file.h"

namespace robottestingframework {
namespace reporters {

bool Reporter::write(const std::string& filename, TestMessage* error) {
    return writeReport(filename, document(), error);
}

}  // namespace reporters
}  // namespace robottestingframework
