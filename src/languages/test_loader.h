// Makes a test case or fixture manager from a file, whatever its language. The in-process
// executor and the worker process both use this.
#pragma once

#include <sys/types.h>

#include <memory>
#include <string>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestCase.h>

namespace robottestingframework {
namespace languages {

// Keeps alive whatever the object needs (a library, an interpreter's module) and the object.
template <typename T>
class Loaded {
public:
    virtual ~Loaded() = default;
    virtual T* get() = 0;
    // Cuts short a call in progress (a fixture's set-up, on Ctrl-C), from any thread; most
    // objects cannot, and do nothing.
    virtual void interrupt() {}
};
using LoadedTest = Loaded<TestCase>;
using LoadedFixture = Loaded<FixtureManager>;

// "dll", "python", "lua", "ruby" or "exec", from the file name and content (SPEC 3.2);
// empty when the file is none of these (for instance, not executable).
std::string typeFromFile(const std::string& path);

// Loads the test at `path` as `type`. nullptr and `error` set (the loader's own words:
// dlerror, a syntax error with file:line, ...) on failure.
std::unique_ptr<LoadedTest> loadTest(const std::string& type, const std::string& path,
                                     std::string& error);
std::unique_ptr<LoadedFixture> loadFixture(const std::string& type, const std::string& path,
                                           std::string& error);

// Pre-starts the runtime of script language `type` in this process, so that forks of it run
// its tests without starting it again (see fork_server_loop.h). False with `error` (why) when
// the language cannot be pre-started; its workers then start it themselves.
bool prestartLanguage(const std::string& type, std::string& error);
// Forks this process once prestartLanguage(type) succeeded, with the runtime's own hooks.
pid_t forkLanguage(const std::string& type);
// In a fork made by forkLanguage(type) that waits for its test: what the runtime does ahead of
// a test (see script_module_interface.h).
void rehearseLanguage(const std::string& type);
// Runs `serve(context)` where forkLanguage(type) may be called: on the runtime's own thread
// when it has one (`hosted` true: this thread then waits), else right here.
int hostLanguage(const std::string& type, int (*serve)(void*), void* context, bool& hosted);

// --isolation none (the runner: executor_choice.cpp): `guard` is called before each exec
// test's program starts, and what it returns (NAME=VALUE, or empty) is added to the program's
// environment: the runner's watchdog of what the tests start, started with the first. None by
// default (workers, the library). POSIX only: on Windows a program's job ends with the runner.
void setExecGuard(std::string (*guard)());

// The types this build supports ("dll", "exec", and the enabled script languages).
bool isSupportedType(const std::string& type);

}  // namespace languages
}  // namespace robottestingframework
