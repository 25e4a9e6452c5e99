// The Windows child-process primitive (platform/job_process.h) and what isolation builds on it:
// a command line quoted as the child reads it back, a job that kills the whole tree, exit codes
// named as crashes, and the worker's request framed over a pipe.
#include <gtest/gtest.h>

#include <windows.h>

#include <filesystem>
#include <string>

#include "build_paths.h"
#include "isolation/request_pipe.h"
#include "platform/file_descriptor.h"
#include "platform/job_process.h"
#include "platform/process.h"

namespace platform = robottestingframework::platform;
namespace isolation = robottestingframework::isolation;
namespace fs = std::filesystem;

namespace {

std::string sleeper() {
    return fs::absolute(fs::path(build_paths::windowsPluginDir()) / "sleeper.exe")
        .make_preferred()
        .string();
}

}  // namespace

TEST(WindowsJobProcess, QuotesArgumentsAsTheChildReadsThem) {
    EXPECT_EQ(platform::quoteArgument("plain"), "plain");
    EXPECT_EQ(platform::quoteArgument(""), "\"\"");
    EXPECT_EQ(platform::quoteArgument("two words"), "\"two words\"");
    EXPECT_EQ(platform::quoteArgument("say \"hi\""), "\"say \\\"hi\\\"\"");
    // Backslashes are doubled only before a quote (here the closing one).
    EXPECT_EQ(platform::quoteArgument("C:\\a b\\"), "\"C:\\a b\\\\\"");
    EXPECT_EQ(platform::quoteArgument("C:\\dir\\x.exe"), "C:\\dir\\x.exe");
}

TEST(WindowsJobProcess, KillEndsTheChildAndTellsItsExitCode) {
    platform::JobProcess child;
    platform::JobProcessOptions options;
    options.argv = {sleeper()};
    std::string error;
    ASSERT_TRUE(child.start(options, error)) << error;
    EXPECT_GT(child.pid(), 0u);
    EXPECT_FALSE(child.ended(100));
    child.kill(7);
    ASSERT_TRUE(child.ended(10000));
    EXPECT_EQ(child.exitCode(), 7u);
}

TEST(WindowsJobProcess, ClosingTheJobEndsTheChild) {
    HANDLE process = nullptr;
    {
        platform::JobProcess child;
        platform::JobProcessOptions options;
        options.argv = {sleeper()};
        std::string error;
        ASSERT_TRUE(child.start(options, error)) << error;
        process = ::OpenProcess(SYNCHRONIZE, FALSE, child.pid());
        ASSERT_NE(process, nullptr);
    }
    EXPECT_EQ(::WaitForSingleObject(process, 10000), WAIT_OBJECT_0);
    ::CloseHandle(process);
}

TEST(WindowsJobProcess, AMissingProgramIsNamedInTheError) {
    platform::JobProcess child;
    platform::JobProcessOptions options;
    options.argv = {"C:\\no\\such\\program.exe"};
    std::string error;
    EXPECT_FALSE(child.start(options, error));
    EXPECT_NE(error.find("cannot run C:\\no\\such\\program.exe"), std::string::npos) << error;
}

TEST(WindowsExitStatus, ExceptionCodesAreCrashesWithNames) {
    const auto violation = platform::ExitStatus::fromWaitStatus(static_cast<int>(0xC0000005UL));
    EXPECT_TRUE(violation.signaled);
    EXPECT_EQ(violation.toString(), "crashed with 0xC0000005 (access violation)");
    EXPECT_EQ(platform::ExitStatus::fromWaitStatus(static_cast<int>(0xC00000FDUL)).toString(),
              "crashed with 0xC00000FD (stack overflow)");
    EXPECT_EQ(platform::ExitStatus::fromWaitStatus(static_cast<int>(0xC000001DUL)).toString(),
              "crashed with 0xC000001D (illegal instruction)");
    const auto exited = platform::ExitStatus::fromWaitStatus(3);
    EXPECT_FALSE(exited.signaled);
    EXPECT_EQ(exited.toString(), "exited with status 3");
}

TEST(WindowsRequestPipe, ARequestCrossesAPipeWhole) {
    platform::FileDescriptor readEnd, writeEnd;
    ASSERT_TRUE(platform::makePipe(readEnd, writeEnd));
    isolation::WorkRequest sent;
    sent.type = "dll";
    sent.path = "C:\\suite\\passing_test.dll";
    sent.param = "--name \"a b\"";
    sent.variables = {"A=1", "B=two words"};
    ASSERT_TRUE(platform::writeAll(writeEnd.get(), isolation::frameRequest(sent)));
    writeEnd.reset();
    isolation::WorkRequest received;
    ASSERT_TRUE(isolation::readRequest(readEnd.get(), received));
    EXPECT_EQ(received.path, sent.path);
    EXPECT_EQ(received.param, sent.param);
    EXPECT_EQ(received.variables, sent.variables);
    // Nothing more: end of file is not a request.
    EXPECT_FALSE(isolation::readRequest(readEnd.get(), received));
}
