// The fork server hands spares to the runner ahead of time (fork_server_loop.h): a request goes
// from the runner straight to a spare, and the runner then claims that spare with the status
// pipe. Driven here through the real worker program and, for the orders the runner cannot
// force, through the protocol itself.
#include <gtest/gtest.h>

#include <errno.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "build_paths.h"
#include "isolation/fork_server_client.h"
#include "isolation/wire_format.h"
#include "isolation/worker_process.h"
#include "platform/clock.h"
#include "platform/fd_passing.h"
#include "platform/file_descriptor.h"

using namespace robottestingframework;
using isolation::SpareNote;
using isolation::WireDecoder;
using isolation::WireKind;
using isolation::WireRecord;
using isolation::WorkRequest;

namespace {

std::string plugin(const std::string& name) {
    return std::string(build_paths::testPluginDir()) + "/" + name + ".so";
}

WorkRequest requestFor(const std::string& name) {
    WorkRequest request;
    request.type = "dll";
    request.path = plugin(name);
    return request;
}

// Every record on `fd` until its end of file (bounded).
std::vector<WireRecord> readAll(int fd, double seconds) {
    std::vector<WireRecord> records;
    WireDecoder decoder;
    platform::Deadline deadline(seconds);
    std::string bytes;
    while (!deadline.expired()) {
        std::vector<bool> ready;
        if (!platform::waitReadable({fd}, deadline.remainingMs(), ready)) {
            break;
        }
        bytes.clear();
        if (platform::readSome(fd, bytes, 4096) <= 0) {
            break;
        }
        decoder.feed(bytes);
        WireRecord record;
        while (decoder.next(record) == WireDecoder::Status::Record) {
            records.push_back(record);
        }
    }
    return records;
}

// The worker's records until it says it finished (true), or it ended without (bounded).
bool finishes(isolation::WorkerProcess& worker) {
    std::vector<WireRecord> records;
    platform::Deadline deadline(10.0);
    while (!worker.exited() && !deadline.expired()) {
        records.clear();
        worker.pump(deadline.remainingMs(), records);
        for (const WireRecord& record : records) {
            if (record.kind == WireKind::Finished) {
                return true;
            }
        }
    }
    return false;
}

// The worker program as a fork server on one end of a socket pair, as ForkServer starts it.
class ServerProcess {
public:
    ServerProcess() {
        EXPECT_TRUE(platform::makeSocketPair(control, theirs, true));
        pid = ::fork();
        if (pid == 0) {
            ::dup2(theirs.get(), 3);
            ::execl(build_paths::workerPath(), "robottestingframework-worker", "--fork-server", "3",
                    static_cast<char*>(nullptr));
            ::_exit(127);
        }
        theirs.reset();
    }
    ~ServerProcess() {
        control.reset();  // end of file: the server ends everything it started
        int status;
        ::waitpid(pid, &status, 0);
    }

    // The next spare it hands over: its pid, and the link its request goes on.
    pid_t nextSpare(platform::FileDescriptor& link) {
        std::vector<bool> ready;
        std::string note;
        std::vector<platform::FileDescriptor> fds;
        SpareNote kind;
        std::int64_t spare = -1;
        if (!platform::waitReadable({control.get()}, 10000, ready) ||
            !platform::receiveWithFds(control.get(), note, fds) || fds.size() != 1 ||
            !isolation::decodeSpareNote(note, kind, spare) || kind != SpareNote::Announced) {
            return -1;
        }
        link = std::move(fds[0]);
        return static_cast<pid_t>(spare);
    }

    platform::FileDescriptor control, theirs;
    pid_t pid = -1;
};

}  // namespace

TEST(SpareNotes, ReadBackAsWrittenAndNeverAsARequest) {
    SpareNote kind;
    std::int64_t pid = 0;
    const std::string note = isolation::encodeSpareNote(SpareNote::Claimed, 123456);
    ASSERT_TRUE(isolation::decodeSpareNote(note, kind, pid));
    EXPECT_EQ(kind, SpareNote::Claimed);
    EXPECT_EQ(pid, 123456);
    WorkRequest request;
    EXPECT_FALSE(isolation::decodeRequest(note, request));
    EXPECT_FALSE(isolation::decodeSpareNote(isolation::encodeRequest(requestFor("x")), kind, pid));
    EXPECT_FALSE(isolation::decodeSpareNote(note.substr(0, note.size() - 1), kind, pid));
    EXPECT_FALSE(isolation::decodeSpareNote("X" + note.substr(1), kind, pid));
}

// The runner knows a worker's pid when it starts it (a timeout can stop it at once), without
// waiting for the server to report it.
TEST(ForkServerSpares, AWorkersPidIsKnownWhenItStarts) {
    isolation::ForkServer server;
    std::string error;
    ASSERT_TRUE(server.start(build_paths::workerPath(), error)) << error;
    isolation::WorkerProcess worker;
    ASSERT_TRUE(worker.start(server, requestFor("passing_test"), error, false)) << error;
    EXPECT_GT(worker.pid(), 0);
    EXPECT_TRUE(finishes(worker));
    server.stop();
}

// A worker may end before the server reads the runner's claim: its end is kept and told when
// the claim comes, after its pid.
TEST(ForkServerSpares, AWorkerThatEndsBeforeItIsClaimedIsToldAtTheClaim) {
    ServerProcess server;
    platform::FileDescriptor link;
    const pid_t spare = server.nextSpare(link);
    ASSERT_GT(spare, 0);
    platform::FileDescriptor channel, theirChannel, outputRead, outputWrite;
    ASSERT_TRUE(platform::makeSocketPair(channel, theirChannel, false));
    ASSERT_TRUE(platform::makePipe(outputRead, outputWrite));
    ASSERT_TRUE(platform::sendWithFds(link.get(),
                                      isolation::encodeRequest(requestFor("crash_segv")),
                                      {theirChannel.get(), outputWrite.get()}));
    theirChannel.reset();
    outputWrite.reset();
    // Reaped by the server (its child): then the pid is gone.
    platform::Deadline deadline(10.0);
    while (::kill(spare, 0) == 0 && !deadline.expired()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_EQ(::kill(spare, 0), -1);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // its reaping noted
    platform::FileDescriptor statusRead, statusWrite;
    ASSERT_TRUE(platform::makePipe(statusRead, statusWrite));
    ASSERT_TRUE(platform::sendWithFds(server.control.get(),
                                      isolation::encodeSpareNote(SpareNote::Claimed, spare),
                                      {statusWrite.get()}));
    statusWrite.reset();
    const std::vector<WireRecord> records = readAll(statusRead.get(), 10.0);
    ASSERT_EQ(records.size(), 2u);
    EXPECT_EQ(records[0].kind, WireKind::Started);
    EXPECT_EQ(records[0].number, spare);
    EXPECT_EQ(records[1].kind, WireKind::Exited);
    const int status = static_cast<int>(records[1].number);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGSEGV) << status;
}

// A spare that died before the runner used it: the runner's request fails on its link, and the
// server hands over another, which runs the test.
TEST(ForkServerSpares, ASpareThatDiedIsReplaced) {
    isolation::ForkServer server;
    std::string error;
    ASSERT_TRUE(server.start(build_paths::workerPath(), error)) << error;
    // The spares are the server's children: end them all.
    platform::Deadline deadline(10.0);
    std::vector<pid_t> killed;
    while (killed.size() < 2 && !deadline.expired()) {
        std::string children;
        FILE* file = std::fopen(("/proc/" + std::to_string(server.pid()) + "/task/" +
                                 std::to_string(server.pid()) + "/children")
                                    .c_str(),
                                "r");
        if (file != nullptr) {
            char buffer[256];
            while (std::fgets(buffer, sizeof buffer, file) != nullptr) {
                children += buffer;
            }
            std::fclose(file);
        }
        killed.clear();
        for (std::size_t at = 0; at < children.size();) {
            const pid_t child = static_cast<pid_t>(std::strtol(children.c_str() + at, nullptr, 10));
            if (child > 0) {
                killed.push_back(child);
            }
            const std::size_t space = children.find(' ', at);
            at = space == std::string::npos ? children.size() : space + 1;
        }
        if (killed.size() < 2) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    ASSERT_EQ(killed.size(), 2u);
    for (pid_t child : killed) {
        ::kill(child, SIGKILL);
    }
    // Gone (reaped by the server) before the runner asks for a worker.
    for (pid_t child : killed) {
        while (::kill(child, 0) == 0 && !deadline.expired()) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    isolation::WorkerProcess worker;
    ASSERT_TRUE(worker.start(server, requestFor("passing_test"), error, false)) << error;
    EXPECT_TRUE(finishes(worker));
    EXPECT_EQ(std::find(killed.begin(), killed.end(), worker.pid()), killed.end());
    server.stop();
}
