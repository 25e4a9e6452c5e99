#include "platform/file_descriptor.h"

// What every platform shares; closing (reset) and the calls on descriptors are in
// file_descriptor-<platform>.cpp.
namespace robottestingframework {
namespace platform {

FileDescriptor& FileDescriptor::operator=(FileDescriptor&& other) noexcept {
    if (this != &other) {
        reset(other.release());
    }
    return *this;
}

int FileDescriptor::release() {
    int fd = fd_;
    fd_ = -1;
    return fd;
}

}  // namespace platform
}  // namespace robottestingframework
