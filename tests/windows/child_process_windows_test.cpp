// The process fixture's Windows child (fixtures/process/child_process-windows.cpp): its output
// read through the pipe while waitReadable waits on its exit handle, exit codes and crashes
// named, a stopped process's whole tree ended with its job, and a refused connection worded from
// Winsock's error (not errno's).
#include <gtest/gtest.h>

#include <windows.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "build_paths.h"
#include "fixtures/process/child_process.h"
#include "fixtures/process/tcp_connector.h"
#include "fixtures/process/waitable_handle-windows.h"

namespace fixtures = robottestingframework::fixtures;
namespace fs = std::filesystem;

namespace {

std::string program(const char* name) {
    return fs::absolute(fs::path(build_paths::windowsPluginDir()) / name).make_preferred().string();
}

fs::path scratch(const char* name) {
    const fs::path folder = fs::path(build_paths::unitTestTmpDir()) / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

// Reads the child's output until it exits (bounded).
std::string outputUntilExit(fixtures::ChildProcess& child) {
    std::string output;
    const double until = fixtures::monotonicSeconds() + 30;
    while (!child.poll() && fixtures::monotonicSeconds() < until) {
        fixtures::waitReadable({child.outputFd(), child.exitFd()}, 1);
        child.readOutput(output);
    }
    while (child.readOutput(output)) {
        fixtures::waitReadable({child.outputFd()}, 0.1);
    }
    return output;
}

bool running(unsigned long pid) {
    HANDLE process = ::OpenProcess(SYNCHRONIZE, FALSE, pid);
    if (process == nullptr) {
        return false;
    }
    const bool alive = ::WaitForSingleObject(process, 5000) == WAIT_TIMEOUT;
    ::CloseHandle(process);
    return alive;
}

}  // namespace

TEST(WindowsFixtureChild, WaitableIdsRoundTripAndAreNoDescriptor) {
    HANDLE event = ::CreateEventA(nullptr, TRUE, FALSE, nullptr);
    const int id = fixtures::waitableId(event);
    EXPECT_TRUE(fixtures::isWaitableId(id));
    EXPECT_FALSE(fixtures::isWaitableId(3));
    EXPECT_FALSE(fixtures::isWaitableId(-1));
    EXPECT_EQ(fixtures::handleOfWaitableId(id), event);
    EXPECT_TRUE(fixtures::waitReadable({id}, 0).empty());
    ::SetEvent(event);
    EXPECT_EQ(fixtures::waitReadable({-1, id}, 1), std::vector<std::size_t>{1});
    ::CloseHandle(event);
}

TEST(WindowsFixtureChild, ReadsItsOutputAndTellsItsExitStatus) {
    const fs::path folder = scratch("fixture_child_output");
    fixtures::ChildProcess child;
    fixtures::ChildOptions options;
    // Relative to the folder, with forward slashes, without .exe: as world files say it. The C
    // run-time of the child ends its lines with \r\n.
    options.argv = {fs::relative(program("world_actor"), folder).generic_string(),
                    "--print",
                    "hello there",
                    "--exit-after",
                    "0",
                    "--exit-code",
                    "7"};
    options.folder = folder.string();
    std::string error;
    ASSERT_TRUE(child.start(options, error)) << error;
    EXPECT_GE(child.exitFd(), 0);
    const std::string output = outputUntilExit(child);
    EXPECT_NE(output.find("hello there\r\n"), std::string::npos) << output;
    EXPECT_TRUE(child.exited());
    EXPECT_EQ(child.status(), "exited with status 7");
    EXPECT_FALSE(child.exitedWithZero());
    EXPECT_EQ(child.outputFd(), -1);  // end of file seen
}

TEST(WindowsFixtureChild, StoppingEndsTheWholeTree) {
    const fs::path folder = scratch("fixture_child_tree");
    fixtures::ChildProcess child;
    fixtures::ChildOptions options;
    options.argv = {program("world_actor.exe"),
                    "--child",
                    program("sleeper.exe"),
                    "--child-pid-file",
                    "child.pid",
                    "--print",
                    "up"};
    options.folder = folder.string();
    std::string error;
    ASSERT_TRUE(child.start(options, error)) << error;
    std::string output;
    const double until = fixtures::monotonicSeconds() + 30;
    while (output.find("\nup\r\n") == std::string::npos && fixtures::monotonicSeconds() < until) {
        fixtures::waitReadable({child.outputFd()}, 1);
        child.readOutput(output);
    }
    ASSERT_NE(output.find("\nup\r\n"), std::string::npos) << output;
    unsigned long grandchild = 0;
    std::ifstream(folder / "child.pid") >> grandchild;
    ASSERT_NE(grandchild, 0u);
    EXPECT_FALSE(child.poll());
    EXPECT_EQ(child.status(), "is running");

    child.signalGroup(15);
    EXPECT_FALSE(fixtures::waitReadable({child.exitFd()}, 10).empty());
    EXPECT_TRUE(child.poll());
    EXPECT_EQ(child.status(), "was ended with its job object");
    EXPECT_FALSE(running(static_cast<unsigned long>(child.pid())));
    EXPECT_FALSE(running(grandchild));
}

TEST(WindowsFixtureChild, AMissingProgramOrFolderIsNamed) {
    const fs::path folder = scratch("fixture_child_missing");
    fixtures::ChildProcess child;
    fixtures::ChildOptions options;
    options.argv = {"./no_such_program"};
    options.folder = folder.string();
    std::string error;
    EXPECT_FALSE(child.start(options, error));
    EXPECT_NE(error.find("no_such_program' does not exist"), std::string::npos) << error;
    options.argv = {"no_such_program"};
    EXPECT_FALSE(child.start(options, error));
    EXPECT_NE(error.find("'no_such_program' was not found in PATH"), std::string::npos) << error;
    options.folder = (folder / "missing").string();
    EXPECT_FALSE(child.start(options, error));
    EXPECT_NE(error.find("the working folder"), std::string::npos) << error;
}

TEST(WindowsFixtureChild, ARefusedConnectionIsWordedByWinsock) {
    // Port 1 of the loopback: nobody listens there. A non-blocking connect may be refused at
    // once or on a later attempt.
    fixtures::TcpConnector connector;
    std::string error;
    ASSERT_TRUE(connector.resolve("127.0.0.1", 1, error)) << error;
    const double until = fixtures::monotonicSeconds() + 10;
    while (error.empty() && fixtures::monotonicSeconds() < until) {
        EXPECT_FALSE(connector.attempt(error));
        ::Sleep(1);
    }
    EXPECT_NE(error.find("Winsock error 10061"), std::string::npos) << error;
    fixtures::TcpConnector nowhere;
    EXPECT_FALSE(nowhere.resolve("no-such-host.invalid", 80, error));
    EXPECT_NE(error.find("cannot resolve host 'no-such-host.invalid'"), std::string::npos) << error;
}
