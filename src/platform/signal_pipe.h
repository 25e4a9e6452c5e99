// Turns asynchronous signals (Ctrl-C, SIGTERM, SIGCHLD) into bytes on a pipe that a poll loop
// or a watcher thread reads: nothing but write() happens inside the handler.
#pragma once

#include <initializer_list>
#include <vector>

namespace robottestingframework {
namespace platform {

// One per process at a time. The handlers are installed by the constructor and the previous
// dispositions restored by the destructor.
class SignalPipe {
public:
    explicit SignalPipe(std::initializer_list<int> signals);
    ~SignalPipe();
    SignalPipe(const SignalPipe&) = delete;
    SignalPipe& operator=(const SignalPipe&) = delete;

    // Readable when a signal arrived.
    int fd() const;
    // The next signal received, or 0 when none is pending.
    int take();
    // Waits up to `timeoutMs` (-1: forever) for a signal; 0 on timeout or wake().
    int wait(int timeoutMs = -1);
    // Ends a wait() of another thread now (it returns 0), e.g. to stop a watcher thread.
    void wake();

    // In a freshly forked child: back to default dispositions, pipe closed. Async-signal-safe.
    static void resetInChild();

private:
    // Makes the pipe (its read end non-blocking) for the constructor; throws when a SignalPipe
    // is there already or no pipe can be made.
    void makeEnds(int& readEnd, int& writeEnd) const;
    // One byte from the pipe: true with the signal (0: a wake()), false when it is empty. Per
    // platform.
    static bool readByte(int& value);

    std::vector<int> signals_;
};

}  // namespace platform
}  // namespace robottestingframework
