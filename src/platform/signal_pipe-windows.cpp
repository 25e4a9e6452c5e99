// Windows: console control events (Ctrl-C, Ctrl-Break, the console closing) through
// SetConsoleCtrlHandler, reported as SIGINT (Ctrl-C) and SIGTERM (the others). Windows runs the
// handler on a thread of its own, so it may write to the pipe like a POSIX handler does.
#include "platform/signal_pipe.h"

#include <io.h>
#include <signal.h>
#include <windows.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

namespace {

int readFd = -1;
std::atomic<int> writeFd{-1};
std::atomic<bool> wantInterrupt{false};
std::atomic<bool> wantTerminate{false};

BOOL WINAPI onControl(DWORD event) {
    const int signal = event == CTRL_C_EVENT ? SIGINT : SIGTERM;
    if ((signal == SIGINT && !wantInterrupt) || (signal == SIGTERM && !wantTerminate)) {
        return FALSE;  // the next handler (by default: end the process)
    }
    const int fd = writeFd;
    if (fd >= 0) {
        unsigned char byte = static_cast<unsigned char>(signal);
        int ignored = ::_write(fd, &byte, 1);
        (void)ignored;
    }
    return TRUE;
}

bool readByte(int& value) {
    std::string byte;
    if (readSome(readFd, byte, 1) == 1) {
        value = static_cast<unsigned char>(byte[0]);
        return true;
    }
    return false;
}

}  // namespace

SignalPipe::SignalPipe(std::initializer_list<int> signals) : signals_(signals) {
    if (readFd >= 0) {
        throw std::logic_error("only one SignalPipe per process");
    }
    FileDescriptor readEnd, writeEnd;
    if (!makePipe(readEnd, writeEnd)) {
        throw std::runtime_error("cannot create the signal pipe");
    }
    setNonBlocking(readEnd.get());
    readFd = readEnd.release();
    writeFd = writeEnd.release();
    wantInterrupt = std::count(signals_.begin(), signals_.end(), SIGINT) > 0;
    wantTerminate = std::count(signals_.begin(), signals_.end(), SIGTERM) > 0;
    ::SetConsoleCtrlHandler(onControl, TRUE);
}

SignalPipe::~SignalPipe() {
    ::SetConsoleCtrlHandler(onControl, FALSE);
    wantInterrupt = false;
    wantTerminate = false;
    const int fd = writeFd.exchange(-1);
    ::_close(fd);
    setNonBlocking(readFd, false);
    ::_close(readFd);
    readFd = -1;
}

int SignalPipe::fd() const {
    return readFd;
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
    return waitReadable({readFd}, timeoutMs, ready) ? take() : 0;
}

void SignalPipe::wake() {
    unsigned char none = 0;  // take() reads it as "no signal"
    int ignored = ::_write(writeFd, &none, 1);
    (void)ignored;
}

void SignalPipe::resetInChild() {
    // No fork on Windows: a child process starts with nothing of ours.
}

}  // namespace platform
}  // namespace robottestingframework
