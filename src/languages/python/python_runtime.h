// The embedded CPython shared by every Python test and fixture of this process: started once,
// never finalized (finalizing and starting again is unreliable), its GIL released between calls.
// Also what the scripts' module `robottestingframework` needs to know: which test or fixture is
// calling, and how its exceptions become the framework's.
#pragma once

#include <pybind11/embed.h>

#include <string>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestCase.h>

// pybind11's types are hidden; what holds them must be too.
#pragma GCC visibility push(hidden)

namespace robottestingframework {
namespace languages {
namespace python {

namespace py = pybind11;

// Starts the interpreter on first use (GIL released afterwards). Safe from any thread.
void ensureInterpreter();

// The pre-started interpreter of a fork server (script_module_interface.h): started with nothing of
// any test loaded. False with `error` when it failed to start.
bool prestartInterpreter(std::string& error);
// fork() with the interpreter's own hooks (os.register_at_fork, its locks, threading's state),
// as os.fork() does; the GIL is released again on both sides.
pid_t forkInterpreter();
// In a fork waiting for its test: rehearses a test (script_module_interface.h). From then on the
// process runs one script (see ScriptModule).
void rehearseInFork();

// Wakes the script running on `thread` (a PyThread ident) out of a blocking call (time.sleep,
// a wait) so that an exception set for it is raised now: a signal whose Python handler raises
// KeyboardInterrupt. Only the interpreter's main thread runs Python handlers; elsewhere the
// call is merely interrupted and resumed.
void wakeScript(unsigned long thread);

// The test or fixture whose script is running; the module's functions report to it.
struct Caller {
    TestCase* test = nullptr;
    FixtureManager* fixture = nullptr;
    unsigned long thread = 0;  // the PyThread ident of the thread of the call (CallerScope sets it)
};

// Makes `caller` the one scripts report to while it lives (GIL held).
class CallerScope {
public:
    explicit CallerScope(Caller caller);
    ~CallerScope();
    CallerScope(const CallerScope&) = delete;
    CallerScope& operator=(const CallerScope&) = delete;

private:
    Caller previous_;
};

// A script file loaded as a fresh module of its own (unique name). Its folder is on sys.path,
// its module and the neighbour modules it imported from that folder are in sys.modules only
// while one of its calls runs (a Call): many scripts can be loaded at once without seeing each
// other's neighbours, and nothing of them stays behind. In a fork of a pre-started interpreter,
// which runs one script and ends, they stay from its first call on (rehearseInFork).
class ScriptModule {
public:
    // nullptr and `error` set (a syntax error as Python shows it, or the traceback of the
    // exception the module raised) on failure. GIL held.
    static std::unique_ptr<ScriptModule> load(const std::string& path, std::string& error);
    // The same from `text`, the content of `path`.
    static std::unique_ptr<ScriptModule> fromSource(const std::string& text,
                                                    const std::string& path, std::string& error);
    ~ScriptModule();  // takes the GIL

    // The module's attribute `name`, or None (GIL held).
    py::object attribute(const char* name) const;

    // Brackets every call into the script (GIL held); flushes sys.stdout and sys.stderr after it.
    class Call {
    public:
        explicit Call(ScriptModule& script);
        ~Call();
        Call(const Call&) = delete;
        Call& operator=(const Call&) = delete;

    private:
        ScriptModule& script_;
    };

private:
    ScriptModule() = default;

    py::object module_;
    py::object scope_;  // its folder and neighbour modules, see kScopeSource
    bool entered_ = false;
};

// Forgets any assertion raised so far (at the start of a call into a script).
void clearPendingAssertion();
// Throws the framework's exception for an assertFail/assertError/assertCritical raised since
// clearPendingAssertion(), even when the script caught it.
void throwPendingAssertion();

// Converts the Python exception in `error` to the framework's exception and throws it:
// assertFail -> TestFailureException, assertError -> TestErrorException, assertCritical ->
// TestCriticalErrorException, anything else -> TestErrorException with the traceback as detail.
[[noreturn]] void rethrow(py::error_already_set& error);

// The exception's traceback, as Python prints it (GIL held).
std::string formatException(py::error_already_set& error);

}  // namespace python
}  // namespace languages
}  // namespace robottestingframework

#pragma GCC visibility pop
