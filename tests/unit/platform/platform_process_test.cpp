// The platform layer: spawning, killing whole process trees, signal names, passing descriptors.
#include <gtest/gtest.h>

#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>

#include "platform/clock.h"
#include "platform/fd_passing.h"
#include "platform/file_descriptor.h"
#include "platform/process.h"
#include "platform/process_tree.h"
#include "platform/signal_name.h"
#include "platform/signal_pipe.h"

using namespace robottestingframework::platform;

namespace {

bool alive(pid_t pid) {
    // A zombie is dead for our purpose.
    std::string stat;
    FILE* file = std::fopen(("/proc/" + std::to_string(pid) + "/stat").c_str(), "r");
    if (file == nullptr) {
        return false;
    }
    char buffer[512] = {};
    std::fread(buffer, 1, sizeof(buffer) - 1, file);
    std::fclose(file);
    const char* close = std::strrchr(buffer, ')');
    return close != nullptr && close[2] != 'Z' && close[2] != 'X';
}

bool waitUntilGone(pid_t pid, double seconds) {
    Deadline deadline(seconds);
    while (alive(pid)) {
        if (deadline.expired()) {
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
}

// A shell that starts a grandchild and prints its pid; both ignore SIGTERM when asked.
pid_t spawnTree(bool ignoreTerm, pid_t& grandchild) {
    FileDescriptor readEnd, writeEnd;
    EXPECT_TRUE(makePipe(readEnd, writeEnd));
    std::string trap = ignoreTerm ? "trap '' TERM; " : "";
    SpawnOptions options;
    options.argv = {"/bin/sh", "-c", trap + "sleep 300 >/dev/null & echo $!; exec 1>&-; wait"};
    options.fds = {{1, writeEnd.get()}};
    std::string error;
    pid_t pid = spawnProcess(options, error);
    EXPECT_GT(pid, 0) << error;
    writeEnd.reset();
    std::string text;
    while (readSome(readEnd.get(), text) > 0) {
    }
    grandchild = static_cast<pid_t>(std::stol(text));
    return pid;
}

}  // namespace

// Sending to a socket whose peer is gone fails with EPIPE and raises no SIGPIPE, whose default
// would end the runner (macOS has no MSG_NOSIGNAL: platform/sigpipe_guard.h), and leaves none
// pending or blocked.
TEST(SendToAGonePeer, FailsWithEpipeAndNoSignal) {
    for (bool packets : {true, false}) {
        FileDescriptor ours, theirs;
        ASSERT_TRUE(makeSocketPair(ours, theirs, packets));
        theirs.reset();
        errno = 0;
        EXPECT_FALSE(sendWithFds(ours.get(), "request", {}));
        EXPECT_EQ(errno, EPIPE);
        EXPECT_FALSE(sendAll(ours.get(), "record"));
        sigset_t pending, mask;
        sigemptyset(&pending);
        ASSERT_EQ(::sigpending(&pending), 0);
        EXPECT_NE(sigismember(&pending, SIGPIPE), 1);
        ASSERT_EQ(::pthread_sigmask(SIG_BLOCK, nullptr, &mask), 0);
        EXPECT_NE(sigismember(&mask, SIGPIPE), 1);
    }
}

TEST(SignalName, NamesTheCommonSignals) {
    EXPECT_EQ(signalName(SIGSEGV), "SIGSEGV");
    EXPECT_EQ(signalName(SIGABRT), "SIGABRT");
    EXPECT_EQ(signalName(SIGKILL), "SIGKILL");
    EXPECT_EQ(signalName(SIGRTMIN + 2), "SIGRTMIN+2");
    EXPECT_EQ(signalName(0), "signal 0");
    EXPECT_EQ(signalDescription(SIGSEGV), "Segmentation fault");
}

TEST(ExitStatus, DescribesExitAndSignal) {
    EXPECT_EQ(ExitStatus::fromWaitStatus(3 << 8).toString(), "exited with status 3");
    ExitStatus killed = ExitStatus::fromWaitStatus(SIGSEGV);
    EXPECT_TRUE(killed.signaled);
    EXPECT_EQ(killed.toString(), "killed by SIGSEGV (Segmentation fault)");
}

TEST(SpawnProcess, ReportsExecFailureInsteadOfAPid) {
    SpawnOptions options;
    options.argv = {"/no/such/program"};
    std::string error;
    EXPECT_EQ(spawnProcess(options, error), -1);
    EXPECT_NE(error.find("/no/such/program"), std::string::npos) << error;
}

TEST(SpawnProcess, ChildLeadsItsOwnGroupAndGetsOnlyTheMappedDescriptors) {
    FileDescriptor readEnd, writeEnd, unrelatedRead, unrelatedWrite;
    ASSERT_TRUE(makePipe(readEnd, writeEnd));
    ASSERT_TRUE(makePipe(unrelatedRead, unrelatedWrite));
    setCloseOnExec(unrelatedWrite.get(), false);  // would leak without the explicit close
    SpawnOptions options;
    options.argv = {"/bin/sh", "-c", "ps -o pgid= -p $$; ls /proc/self/fd | wc -l"};
    options.fds = {{1, writeEnd.get()}};
    std::string error;
    pid_t pid = spawnProcess(options, error);
    ASSERT_GT(pid, 0) << error;
    writeEnd.reset();
    std::string text;
    while (readSome(readEnd.get(), text) > 0) {
    }
    int status;
    ASSERT_TRUE(waitChild(pid, 10, status));
    EXPECT_EQ(std::stol(text), pid) << "process group id";
    // ls sees 0, 1, 2 and its own directory descriptor.
    EXPECT_EQ(std::stol(text.substr(text.find('\n') + 1)), 4) << text;
}

TEST(ProcessTree, DescendantsIncludeGrandchildren) {
    pid_t grandchild;
    pid_t child = spawnTree(false, grandchild);
    std::vector<pid_t> found = descendantsOf(::getpid());
    EXPECT_NE(std::find(found.begin(), found.end(), child), found.end());
    EXPECT_NE(std::find(found.begin(), found.end(), grandchild), found.end());
    EXPECT_EQ(descendantsOf(child), std::vector<pid_t>{grandchild});
    stopChildGroup(child, 1.0);
    EXPECT_TRUE(waitUntilGone(grandchild, 5));
}

TEST(ProcessTree, DescendantsIncludeChildrenStartedByAnotherThread) {
    // The kernel lists a process's children per thread (/proc/<pid>/task/<tid>/children): a
    // child forked by a thread other than the main one is a descendant all the same. The
    // thread lives on while we look (when it ends, its children pass to the main thread).
    std::mutex mutex;
    std::condition_variable changed;
    pid_t child = 0;
    bool looked = false;
    std::thread starter([&] {
        SpawnOptions options;
        options.argv = {"/bin/sh", "-c", "exec sleep 300"};
        std::string error;
        const pid_t started = spawnProcess(options, error);
        std::unique_lock<std::mutex> lock(mutex);
        child = started;
        changed.notify_all();
        changed.wait(lock, [&] { return looked; });
    });
    std::vector<pid_t> found;
    {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [&] { return child != 0; });
        found = descendantsOf(::getpid());
        looked = true;
        changed.notify_all();
    }
    starter.join();
    ASSERT_GT(child, 0);
    EXPECT_NE(std::find(found.begin(), found.end(), child), found.end());
    stopChildGroup(child, 1.0);
}

TEST(ProcessTree, DescendantsLeaveZombiesOut) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::_exit(0);
    }
    // Until reaped, the child is a zombie: nothing to stop, so not a descendant.
    siginfo_t info{};
    ASSERT_EQ(::waitid(P_PID, static_cast<id_t>(child), &info, WEXITED | WNOWAIT), 0);
    std::vector<pid_t> found = descendantsOf(::getpid());
    EXPECT_EQ(std::find(found.begin(), found.end(), child), found.end());
    int status;
    EXPECT_TRUE(waitChild(child, 5, status));
    EXPECT_TRUE(WIFEXITED(status));
}

TEST(WaitChild, ReturnsTheStatusOfAChildThatEndsWithinTheTimeout) {
    SpawnOptions options;
    options.argv = {"/bin/sh", "-c", "sleep 0.05; exit 3"};
    std::string error;
    const pid_t child = spawnProcess(options, error);
    ASSERT_GT(child, 0) << error;
    int status = 0;
    ASSERT_TRUE(waitChild(child, 10, status));
    EXPECT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 3);
}

TEST(WaitChild, GivesUpAtTheTimeoutAndLeavesTheChildToBeWaitedFor) {
    SpawnOptions options;
    options.argv = {"/bin/sh", "-c", "exec sleep 300"};
    std::string error;
    const pid_t child = spawnProcess(options, error);
    ASSERT_GT(child, 0) << error;
    int status = 0;
    EXPECT_FALSE(waitChild(child, 0.05, status));
    ::kill(child, SIGKILL);
    ASSERT_TRUE(waitChild(child, 10, status));
    EXPECT_TRUE(WIFSIGNALED(status));
}

TEST(ProcessTree, StopChildGroupKillsAGroupThatIgnoresSigterm) {
    pid_t grandchild;
    pid_t child = spawnTree(true, grandchild);
    double start = monotonicSeconds();
    int status = stopChildGroup(child, 0.2);
    double took = monotonicSeconds() - start;
    ExitStatus ending = ExitStatus::fromWaitStatus(status);
    EXPECT_TRUE(ending.signaled);
    EXPECT_EQ(ending.signal, SIGKILL);
    EXPECT_GE(took, 0.2);
    EXPECT_LT(took, 3.0);
    EXPECT_TRUE(waitUntilGone(grandchild, 5)) << "the grandchild went with the group";
}

TEST(ProcessTree, KillDescendantsReachesProcessesThatLeftTheGroup) {
    // The grandchild starts a session of its own: only the /proc walk finds it.
    FileDescriptor readEnd, writeEnd;
    ASSERT_TRUE(makePipe(readEnd, writeEnd));
    SpawnOptions options;
    options.argv = {"/bin/sh", "-c", "setsid sleep 300 >/dev/null & echo $!; exec 1>&-; wait"};
    options.fds = {{1, writeEnd.get()}};
    std::string error;
    pid_t child = spawnProcess(options, error);
    ASSERT_GT(child, 0) << error;
    writeEnd.reset();
    std::string text;
    while (readSome(readEnd.get(), text) > 0) {
    }
    pid_t grandchild = static_cast<pid_t>(std::stol(text));
    EXPECT_EQ(killDescendants(::getpid()) >= 2, true);
    int status;
    EXPECT_TRUE(waitChild(child, 5, status));
    EXPECT_TRUE(waitUntilGone(grandchild, 5));
}

// The pid a forked helper wrote on `readEnd` before it ended (then reaped).
pid_t pidFromHelper(pid_t helper, FileDescriptor& readEnd) {
    std::string text;
    while (readSome(readEnd.get(), text) > 0) {
    }
    int status;
    EXPECT_TRUE(waitChild(helper, 5, status));
    return text.empty() ? -1 : static_cast<pid_t>(std::stol(text));
}

// A program started with a parent-death signal ends when the process that started it ends,
// even by SIGKILL: prctl on Linux, a guard on a lifeline pipe in the portable build.
TEST(SpawnProcess, ParentDeathSignalEndsTheChildWhenItsParentIsKilled) {
    FileDescriptor readEnd, writeEnd;
    ASSERT_TRUE(makePipe(readEnd, writeEnd));
    const pid_t parent = ::fork();
    ASSERT_GE(parent, 0);
    if (parent == 0) {
        SpawnOptions options;
        options.argv = {"/bin/sleep", "30"};
        options.parentDeathSignal = SIGKILL;
        std::string error;
        const pid_t child = spawnProcess(options, error);
        const std::string text = std::to_string(child);
        writeAll(writeEnd.get(), text);
        writeEnd.reset();
        ::kill(::getpid(), SIGKILL);
    }
    writeEnd.reset();
    const pid_t child = pidFromHelper(parent, readEnd);
    ASSERT_GT(child, 0);
    EXPECT_TRUE(waitUntilGone(child, 5)) << "the program outlived the process that started it";
    ::kill(child, SIGKILL);
}

// The fork server's workers: forked, not exec'd, they ask for the signal themselves.
TEST(SetParentDeathSignal, AForkedChildEndsWithItsParent) {
    FileDescriptor readEnd, writeEnd;
    ASSERT_TRUE(makePipe(readEnd, writeEnd));
    const pid_t parent = ::fork();
    ASSERT_GE(parent, 0);
    if (parent == 0) {
        prepareChildrenParentDeath();
        const pid_t child = ::fork();
        if (child == 0) {
            readEnd.reset();
            writeEnd.reset();
            const bool armed = setParentDeathSignal(SIGKILL);
            for (int i = 0; armed && i < 300; ++i) {
                ::usleep(100000);
            }
            ::_exit(0);
        }
        writeAll(writeEnd.get(), std::to_string(child));
        writeEnd.reset();
        ::usleep(200000);  // time for the child to arm the signal
        ::kill(::getpid(), SIGKILL);
    }
    writeEnd.reset();
    const pid_t child = pidFromHelper(parent, readEnd);
    ASSERT_GT(child, 0);
    EXPECT_TRUE(waitUntilGone(child, 5)) << "the forked child outlived its parent";
    ::kill(child, SIGKILL);
}

TEST(FdPassing, DescriptorsArriveWithTheMessage) {
    FileDescriptor a, b, readEnd, writeEnd;
    ASSERT_TRUE(makeSocketPair(a, b, true));
    ASSERT_TRUE(makePipe(readEnd, writeEnd));
    ASSERT_TRUE(sendWithFds(a.get(), "hello", {writeEnd.get()}));
    writeEnd.reset();
    std::string data;
    std::vector<FileDescriptor> fds;
    ASSERT_TRUE(receiveWithFds(b.get(), data, fds));
    EXPECT_EQ(data, "hello");
    ASSERT_EQ(fds.size(), 1u);
    ASSERT_TRUE(writeAll(fds[0].get(), "through the passed pipe"));
    fds.clear();
    std::string text;
    while (readSome(readEnd.get(), text) > 0) {
    }
    EXPECT_EQ(text, "through the passed pipe");
    a.reset();
    EXPECT_FALSE(receiveWithFds(b.get(), data, fds)) << "end of stream when the peer is gone";
}

TEST(SignalPipe, SignalBecomesReadableByte) {
    SignalPipe signals({SIGUSR1});
    EXPECT_EQ(signals.take(), 0);
    ::kill(::getpid(), SIGUSR1);
    EXPECT_EQ(signals.wait(2000), SIGUSR1);
    EXPECT_EQ(signals.wait(10), 0);
}

TEST(SignalPipe, WakeEndsAWaitOfAnotherThreadAtOnce) {
    SignalPipe signals({SIGUSR1});
    int got = -1;
    Deadline bound(5.0);
    std::thread waiter([&] { got = signals.wait(10000); });
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    signals.wake();
    waiter.join();
    EXPECT_EQ(got, 0) << "a wake is not a signal";
    EXPECT_FALSE(bound.expired()) << "the wait did not end at the wake";
}

TEST(FdPassing, PacketsOfEverySizeArriveWhole) {
    FileDescriptor a, b;
    ASSERT_TRUE(makeSocketPair(a, b, true));
    std::string data;
    std::vector<FileDescriptor> fds;
    for (std::size_t size : {std::size_t(1), std::size_t(300), kMaxPacket / 2, kMaxPacket}) {
        const std::string sent(size, 'x');
        ASSERT_TRUE(sendWithFds(a.get(), sent, {a.get()})) << size;
        ASSERT_TRUE(receiveWithFds(b.get(), data, fds)) << size;
        EXPECT_EQ(data, sent);
        EXPECT_EQ(fds.size(), 1u) << "the descriptor comes with its packet, once";
    }
}

// A suite's param or environment of any size reaches the fork server (it said "Message too
// long" over 128 KiB).
TEST(FdPassing, MessagesLongerThanAPacketArriveWholeWithTheirDescriptors) {
    FileDescriptor a, b;
    ASSERT_TRUE(makeSocketPair(a, b, true));
    std::string data;
    std::vector<FileDescriptor> fds;
    for (std::size_t size : {kMaxPacket - 1, kMaxPacket + 1, std::size_t(8 * 1024 * 1024)}) {
        std::string sent(size, 'x');
        sent[size / 2] = '\0';
        ASSERT_TRUE(sendWithFds(a.get(), sent, {a.get(), b.get()})) << size;
        ASSERT_TRUE(receiveWithFds(b.get(), data, fds)) << size;
        EXPECT_EQ(data, sent) << size;
        EXPECT_EQ(fds.size(), 2u) << "only the descriptors the sender passed";
    }
    ASSERT_TRUE(sendWithFds(a.get(), "", {}));
    ASSERT_TRUE(receiveWithFds(b.get(), data, fds));
    EXPECT_EQ(data, "");
    EXPECT_TRUE(fds.empty());
}

TEST(Deadline, NeverAndExpired) {
    Deadline never(0);
    EXPECT_TRUE(never.never());
    EXPECT_FALSE(never.expired());
    EXPECT_EQ(never.remainingMs(), -1);
    EXPECT_EQ(never.remainingMs(50), 50);
    Deadline soon(0.01);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_TRUE(soon.expired());
    EXPECT_EQ(soon.remainingMs(), 0);
}

// The pre-started interpreters refuse to fork a process that runs more than one thread.
TEST(Process, ThreadCountSeesAThreadStartAndEnd) {
    std::size_t before = robottestingframework::platform::threadCount();
    ASSERT_GE(before, 1u);
    std::mutex mutex;
    std::condition_variable changed;
    bool started = false;
    bool release = false;
    std::thread thread([&] {
        std::unique_lock<std::mutex> lock(mutex);
        started = true;
        changed.notify_all();
        changed.wait(lock, [&] { return release; });
    });
    {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [&] { return started; });
    }
    EXPECT_EQ(robottestingframework::platform::threadCount(), before + 1);
    {
        std::lock_guard<std::mutex> lock(mutex);
        release = true;
    }
    changed.notify_all();
    thread.join();
    // Joined is not yet unlinked: the count falls a moment later.
    EXPECT_EQ(robottestingframework::platform::threadCountSettled(before, 2000), before);
}

TEST(Process, ThreadCountSettledReturnsAtOnceWhenTheCountIsLowEnough) {
    std::size_t now = robottestingframework::platform::threadCount();
    auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(robottestingframework::platform::threadCountSettled(now, 0), now);
    EXPECT_EQ(robottestingframework::platform::threadCountSettled(now + 1, 5000), now);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}
