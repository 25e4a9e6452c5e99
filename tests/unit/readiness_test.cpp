// The readiness checks of the process fixture, one at a time.
#include "fixtures/process/readiness.h"

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "process_test_helpers.h"

using namespace robottestingframework::fixtures;

namespace {

// A TCP socket bound to a free port of 127.0.0.1, listening only when asked.
class BoundSocket {
public:
    BoundSocket() {
        fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        ::bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address);
        socklen_t size = sizeof address;
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &size);
        port_ = ntohs(address.sin_port);
    }
    ~BoundSocket() { ::close(fd_); }
    void listen() { ::listen(fd_, 4); }
    int port() const { return port_; }

private:
    int fd_ = -1;
    int port_ = 0;
};

ReadyCheck checkOf(ReadyCheck::Kind kind, double timeout = 5) {
    ReadyCheck check;
    check.kind = kind;
    check.timeout = timeout;
    return check;
}

std::unique_ptr<Readiness> make(const ReadyCheck& check, double started) {
    ChildOptions context;
    context.folder = "/";
    std::string error;
    auto readiness = makeReadiness(check, started, context, error);
    EXPECT_TRUE(readiness) << error;
    return readiness;
}

// Polls `check` when due until it passes or `limit` seconds go by; returns when it passed.
double pollUntilPassed(Readiness& check, double limit) {
    const double end = monotonicSeconds() + limit;
    while (monotonicSeconds() < end) {
        double now = monotonicSeconds();
        if (check.nextPoll(now) <= now && check.poll(now)) {
            return now;
        }
        waitReadable(check.fds(), std::min(0.001, std::max(0.0, check.nextPoll(now) - now)));
    }
    return -1;
}

}  // namespace

TEST(Readiness, PortPassesOnlyOnceSomethingListens) {
    BoundSocket socket;
    std::string error;
    EXPECT_FALSE(tcpAccepts("127.0.0.1", socket.port(), error));
    EXPECT_NE(error.find("refused"), std::string::npos) << error;

    ReadyCheck spec = checkOf(ReadyCheck::Kind::Port);
    spec.port = socket.port();
    auto check = make(spec, monotonicSeconds());
    EXPECT_FALSE(check->poll(monotonicSeconds()));
    EXPECT_NE(check->lastObservation().find("refused"), std::string::npos);
    socket.listen();
    EXPECT_TRUE(check->poll(monotonicSeconds()));
    EXPECT_TRUE(check->passed());
}

TEST(Readiness, PortIsPolledEveryMillisecondAtFirst) {
    ReadyCheck spec = checkOf(ReadyCheck::Kind::Port);
    spec.port = 1;
    const double now = monotonicSeconds();
    auto check = make(spec, now);
    EXPECT_LE(check->nextPoll(now), now);  // due at once
    check->poll(now);
    EXPECT_DOUBLE_EQ(check->nextPoll(now), now + 0.001);
    check->poll(now + 10);  // later on, a little less often
    EXPECT_DOUBLE_EQ(check->nextPoll(now + 10), now + 10.005);
}

TEST(Readiness, AHostThatDoesNotResolveIsAnError) {
    ReadyCheck spec = checkOf(ReadyCheck::Kind::Port);
    spec.host = "no-such-host.invalid";
    spec.port = 80;
    ChildOptions context;
    std::string error;
    EXPECT_FALSE(makeReadiness(spec, 0, context, error));
    EXPECT_NE(error.find("cannot resolve host 'no-such-host.invalid'"), std::string::npos) << error;
}

TEST(Readiness, FilePassesWhenTheFileAppears) {
    const auto folder = rtf_process_test::freshFolder();
    ReadyCheck spec = checkOf(ReadyCheck::Kind::File);
    spec.path = (folder / "ready.flag").string();
    auto check = make(spec, monotonicSeconds());
    EXPECT_FALSE(check->poll(monotonicSeconds()));
    rtf_process_test::writeFile(folder / "ready.flag", "");
    EXPECT_TRUE(check->poll(monotonicSeconds()));
}

TEST(Readiness, DelayPassesWhenItIsOver) {
    ReadyCheck spec = checkOf(ReadyCheck::Kind::Delay);
    spec.delay = 0.5;
    auto check = make(spec, 100);
    EXPECT_DOUBLE_EQ(check->nextPoll(100), 100.5);
    EXPECT_FALSE(check->poll(100.4));
    EXPECT_TRUE(check->poll(100.5));
    EXPECT_DOUBLE_EQ(check->passedAt(), 100.5);
}

TEST(Readiness, OutputPassesOnAMatchingLine) {
    ReadyCheck spec = checkOf(ReadyCheck::Kind::Output);
    spec.pattern = "listening on port \\d+";
    auto check = make(spec, 0);
    check->line("starting", 1);
    EXPECT_FALSE(check->passed());
    check->line("[info] listening on port 8080 now", 2);
    EXPECT_TRUE(check->passed());
    EXPECT_DOUBLE_EQ(check->passedAt(), 2);
}

TEST(Readiness, OutputMatchesInTimeLinearInTheLine) {
    // Backtracking (std::regex) took 28 s for 18 a's and minutes for 24: far past any deadline.
    ReadyCheck spec = checkOf(ReadyCheck::Kind::Output);
    spec.pattern = "^(a*)*b$";
    auto check = make(spec, 0);
    const double began = monotonicSeconds();
    check->line(std::string(4096, 'a'), 1);
    EXPECT_FALSE(check->passed());
    check->line(std::string(4095, 'a') + "b", 2);
    EXPECT_TRUE(check->passed());
    EXPECT_LT(monotonicSeconds() - began, 1.0);
}

TEST(Readiness, DeadlineIsCountedFromTheProcessStart) {
    ReadyCheck spec = checkOf(ReadyCheck::Kind::Output, 3);
    spec.pattern = "never";
    auto check = make(spec, 10);
    EXPECT_FALSE(check->expired(12.9));
    EXPECT_TRUE(check->expired(13));
}

TEST(Readiness, ProbePassesWhenTheCommandExitsWithZero) {
    const auto folder = rtf_process_test::freshFolder();
    ReadyCheck spec = checkOf(ReadyCheck::Kind::Probe);
    spec.argv = {"/bin/sh", "-c", "test -e " + (folder / "up").string()};
    spec.interval = 0.01;
    auto check = make(spec, monotonicSeconds());
    EXPECT_LT(pollUntilPassed(*check, 0.2), 0);  // not yet: the probe keeps failing
    EXPECT_NE(check->lastObservation().find("exited with status 1"), std::string::npos)
        << check->lastObservation();
    rtf_process_test::writeFile(folder / "up", "");
    EXPECT_GT(pollUntilPassed(*check, 2), 0);
}

TEST(Readiness, ProbeOutputExplainsItsFailure) {
    ReadyCheck spec = checkOf(ReadyCheck::Kind::Probe);
    spec.argv = {"/bin/sh", "-c", "echo 'service is down'; exit 3"};
    auto check = make(spec, monotonicSeconds());
    EXPECT_LT(pollUntilPassed(*check, 0.3), 0);
    EXPECT_NE(check->lastObservation().find("exited with status 3"), std::string::npos);
    EXPECT_NE(check->lastObservation().find("service is down"), std::string::npos)
        << check->lastObservation();
}

TEST(Readiness, ProbeThatCannotStartSaysWhy) {
    ReadyCheck spec = checkOf(ReadyCheck::Kind::Probe);
    spec.argv = {"no-such-probe-program"};
    auto check = make(spec, monotonicSeconds());
    EXPECT_FALSE(check->poll(monotonicSeconds()));
    EXPECT_NE(check->lastObservation().find("'no-such-probe-program' was not found in PATH"),
              std::string::npos)
        << check->lastObservation();
}
