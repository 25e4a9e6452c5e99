#include "platform/signal_pipe.h"

#include <stdexcept>

#include "platform/file_descriptor.h"

// What every platform shares; the handlers and the pipe's own variables are in
// signal_pipe-<platform>.cpp.
namespace robottestingframework {
namespace platform {

void SignalPipe::makeEnds(int& readEnd, int& writeEnd) const {
    if (fd() >= 0) {
        throw std::logic_error("only one SignalPipe per process");
    }
    FileDescriptor reading, writing;
    if (!makePipe(reading, writing)) {
        throw std::runtime_error("cannot create the signal pipe");
    }
    setNonBlocking(reading.get());
    readEnd = reading.release();
    writeEnd = writing.release();
}

int SignalPipe::take() {
    int signal = 0;
    return readByte(signal) ? signal : 0;
}

int SignalPipe::wait(int timeoutMs) {
    int signal = 0;
    if (readByte(signal)) {
        return signal;  // a wake() that came before the wait ends it too
    }
    std::vector<bool> ready;
    return waitReadable({fd()}, timeoutMs, ready) ? take() : 0;
}

}  // namespace platform
}  // namespace robottestingframework
