#include "reporters/standard_output_descriptor.h"

#include <io.h>

namespace robottestingframework {
namespace reporters {

int duplicateDescriptor(int fd) {
    return ::_dup(fd);
}

bool pointDescriptor(int source, int target) {
    return ::_dup2(source, target) == 0;
}

void closeDescriptor(int fd) {
    ::_close(fd);
}

}  // namespace reporters
}  // namespace robottestingframework
