#include "platform/signal_pipe.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace platform {

namespace {

int readFd = -1;
volatile sig_atomic_t writeFd = -1;
struct sigaction previous[NSIG];
int installed[NSIG];
int installedCount = 0;

extern "C" void onSignal(int signal) {
    int saved = errno;
    unsigned char byte = static_cast<unsigned char>(signal);
    if (writeFd >= 0) {
        // A full pipe loses the byte, but the reader then has plenty of others to wake it.
        ssize_t ignored = ::write(writeFd, &byte, 1);
        (void)ignored;
    }
    errno = saved;
}

}  // namespace

SignalPipe::SignalPipe(std::initializer_list<int> signals) : signals_(signals) {
    int writeEnd = -1;
    makeEnds(readFd, writeEnd);
    setNonBlocking(writeEnd);  // a handler never waits
    writeFd = writeEnd;
    installedCount = 0;
    for (int signal : signals_) {
        struct sigaction action {};
        action.sa_handler = onSignal;
        sigemptyset(&action.sa_mask);
        // SA_RESTART keeps unrelated blocking calls going; poll loops wake on the pipe.
        action.sa_flags = SA_RESTART | (signal == SIGCHLD ? SA_NOCLDSTOP : 0);
        ::sigaction(signal, &action, &previous[signal]);
        installed[installedCount++] = signal;
    }
}

SignalPipe::~SignalPipe() {
    for (int signal : signals_) {
        ::sigaction(signal, &previous[signal], nullptr);
    }
    installedCount = 0;
    int fd = writeFd;
    writeFd = -1;
    ::close(fd);
    ::close(readFd);
    readFd = -1;
}

int SignalPipe::fd() const {
    return readFd;
}

bool SignalPipe::readByte(int& value) {
    unsigned char byte;
    for (;;) {
        ssize_t n = ::read(readFd, &byte, 1);
        if (n == 1) {
            value = byte;
            return true;
        }
        if (n < 0 && errno == EINTR) {
            continue;
        }
        return false;
    }
}

void SignalPipe::wake() {
    unsigned char none = 0;  // take() reads it as "no signal"
    ssize_t ignored = ::write(writeFd, &none, 1);
    (void)ignored;
}

void SignalPipe::resetInChild() {
    struct sigaction action {};
    action.sa_handler = SIG_DFL;
    sigemptyset(&action.sa_mask);
    for (int i = 0; i < installedCount; ++i) {
        ::sigaction(installed[i], &action, nullptr);
    }
    if (writeFd >= 0) {
        ::close(writeFd);
        ::close(readFd);
        writeFd = -1;
        readFd = -1;
    }
}

}  // namespace platform
}  // namespace robottestingframework
