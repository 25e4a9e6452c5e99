// Windows: console control events (Ctrl-C, Ctrl-Break, the console closing) through
// SetConsoleCtrlHandler, reported as SIGINT (Ctrl-C) and SIGTERM (the others). Windows runs the
// handler on a thread of its own, so it may write to the pipe like a POSIX handler does.
#include "platform/signal_pipe.h"

#include <io.h>
#include <signal.h>
#include <windows.h>

#include <algorithm>
#include <atomic>

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

}  // namespace

bool SignalPipe::readByte(int& value) {
    std::string byte;
    if (readSome(readFd, byte, 1) == 1) {
        value = static_cast<unsigned char>(byte[0]);
        return true;
    }
    return false;
}

SignalPipe::SignalPipe(std::initializer_list<int> signals) : signals_(signals) {
    int writeEnd = -1;
    makeEnds(readFd, writeEnd);
    writeFd = writeEnd;
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
