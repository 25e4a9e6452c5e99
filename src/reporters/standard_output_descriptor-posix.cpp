#include "reporters/standard_output_descriptor.h"

#include <fcntl.h>
#include <unistd.h>

namespace robottestingframework {
namespace reporters {

int duplicateDescriptor(int fd) {
    return ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
}

bool pointDescriptor(int source, int target) {
    return ::dup2(source, target) >= 0;
}

void closeDescriptor(int fd) {
    ::close(fd);
}

}  // namespace reporters
}  // namespace robottestingframework
