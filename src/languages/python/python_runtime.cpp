#include "languages/python/python_runtime.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include <robottestingframework/Asserter.h>
#include <robottestingframework/Exception.h>

namespace robottestingframework {
namespace languages {
namespace python {

namespace {

// Guarded by the GIL, like everything Python.
Caller g_caller;
PyObject* g_failure = nullptr;   // robottestingframework.TestFailure
PyObject* g_error = nullptr;     // robottestingframework.TestError
PyObject* g_critical = nullptr;  // robottestingframework.TestCriticalError

// The last assertion raised by a script (kind 0: none), so that catching it does not hide it.
int g_pendingKind = 0;  // 1 failure, 2 error, 3 critical
TestMessage g_pendingMessage;

// The file and line of the Python code that called into the module.
TestMessage messageHere(const std::string& text, const std::string& detail = "") {
    TestMessage message(text, detail);
    PyFrameObject* frame = PyEval_GetFrame();  // borrowed
    if (frame != nullptr) {
        auto code =
            py::reinterpret_steal<py::object>(reinterpret_cast<PyObject*>(PyFrame_GetCode(frame)));
        message.setSourceFileName(py::str(code.attr("co_filename")));
        message.setSourceLineNumber(static_cast<unsigned int>(PyFrame_GetLineNumber(frame)));
    }
    return message;
}

// A Python number (int, float, numpy scalar) as a double; a TypeError for anything else.
double number(const py::object& value) {
    const double result = PyFloat_AsDouble(value.ptr());
    if (result == -1.0 && PyErr_Occurred() != nullptr) {
        throw py::error_already_set();
    }
    return result;
}

TestCase* currentTest() {
    return g_caller.test != nullptr ? g_caller.test : TestCase::current();
}

// A thread a test started carries that test (its id and name, `_rtf_test`, stamped by
// kThreadOwnerSource): with --isolation none the runner goes on to the next test while the
// thread may still run. What it reports after its test ended belongs to that test, never to
// the one running then: it is dropped with a warning naming its test
// (docs/tutorial/other-languages.md). Empty when the calling thread is the call's own, carries no
// test, or its test is the running one.
std::string endedOwner() {
    if (g_caller.test != nullptr && PyThread_get_thread_ident() == g_caller.thread) {
        return "";
    }
    py::object thread = py::module_::import("threading").attr("current_thread")();
    py::object owner = py::getattr(thread, "_rtf_test", py::none());
    if (owner.is_none()) {
        return "";
    }
    const py::tuple stamp = owner;
    const TestCase* running = g_caller.fixture == nullptr ? currentTest() : nullptr;
    if (running != nullptr && running->getId() == stamp[0].cast<std::uint64_t>()) {
        return "";
    }
    return py::str(stamp[1]);
}

// The warning of a late call of a thread of `owner` (endedOwner), on stderr as a message with
// no running test is (Asserter): the event itself is dropped.
void warnLate(const std::string& owner, const char* call, const TestMessage& message) {
    const std::string where = message.getSourceLocation();
    std::fprintf(stderr,
                 "robottestingframework: warning: a thread of test \"%s\" called %s after that "
                 "test ended; dropped: %s%s%s%s\n",
                 owner.c_str(), call, message.toString().c_str(), where.empty() ? "" : " [",
                 where.c_str(), where.empty() ? "" : "]");
}

// True (and warned) when the calling thread's test ended: the caller drops the event.
bool late(const char* call, const TestMessage& message) {
    const std::string owner = endedOwner();
    if (owner.empty()) {
        return false;
    }
    warnLate(owner, call, message);
    return true;
}

bool truth(const py::handle& value) {
    int result = PyObject_IsTrue(value.ptr());
    if (result < 0) {
        throw py::error_already_set();
    }
    return result != 0;
}

void report(const TestMessage& message) {
    if (g_caller.fixture != nullptr) {
        Asserter::report(message, g_caller.fixture);
    } else {
        Asserter::report(message, currentTest());
    }
}

// Raises `type` with (message, file, line): the wrapper turns it into the framework's exception.
[[noreturn]] void raise(PyObject* type, const py::object& text) {
    TestMessage here = messageHere(py::str(text));
    // Kept for the call's end only when it is raised on the call's thread, or on a thread of
    // the running test: a thread of an ended test raises it in that thread alone.
    if (g_caller.test == nullptr || PyThread_get_thread_ident() == g_caller.thread ||
        endedOwner().empty()) {
        g_pendingKind = type == g_failure ? 1 : (type == g_critical ? 3 : 2);
        g_pendingMessage = here;
    }
    py::tuple args =
        py::make_tuple(here.getMessage(), here.getSourceFileName(), here.getSourceLineNumber());
    PyErr_SetObject(type, args.ptr());
    throw py::error_already_set();
}

std::string join(const py::handle& lines) {
    std::string text;
    for (const auto& line : lines) {
        text += py::str(line).cast<std::string>();
    }
    return text;
}

std::string trimEnd(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) {
        text.pop_back();
    }
    return text;
}

// Adds an active virtual environment's packages in front of the system's, as its own python
// would see them.
void addVirtualEnvironment() {
    const char* venv = std::getenv("VIRTUAL_ENV");
    if (venv == nullptr || *venv == '\0') {
        return;
    }
    py::module_ sys = py::module_::import("sys");
    py::tuple version = sys.attr("version_info");
    std::string sitePackages = std::string(venv) + "/lib/python" +
                               py::str(version[0]).cast<std::string>() + "." +
                               py::str(version[1]).cast<std::string>() + "/site-packages";
    if (!std::filesystem::is_directory(sitePackages)) {
        return;
    }
    py::list path = sys.attr("path");
    py::list before = path.attr("copy")();
    py::module_::import("site").attr("addsitedir")(sitePackages);
    py::list added;
    for (const auto& entry : path) {
        if (!before.contains(entry)) {
            added.append(entry);
        }
    }
    for (const auto& entry : added) {
        path.attr("remove")(entry);
    }
    for (std::size_t i = added.size(); i > 0; --i) {
        path.insert(0, added[i - 1]);
    }
}

// Swaps a script's folder and neighbour modules in and out of sys.path and sys.modules.
const char* const kScopeSource = R"(
import os
import sys

class Scope:
    def __init__(self, folder, name, module):
        self.folder = folder
        self.prefix = os.path.join(folder, "")
        self.name = name
        self.module = module
        self.stash = {}
        self.before = set()

    def enter(self):
        sys.path.insert(0, self.folder)
        sys.modules.update(self.stash)
        # Registered while it runs: dataclasses, pickle and typing look classes' modules up.
        sys.modules[self.name] = self.module
        self.before = set(sys.modules)

    def leave(self):
        try:
            sys.path.remove(self.folder)
        except ValueError:
            pass
        sys.modules.pop(self.name, None)
        for name in list(self.stash):
            module = sys.modules.pop(name, None)
            if module is not None:
                self.stash[name] = module
        for name in sys.modules.keys() - self.before:
            file = getattr(sys.modules[name], "__file__", None)
            if isinstance(file, str) and os.path.abspath(file).startswith(self.prefix):
                self.stash[name] = sys.modules.pop(name)
)";

py::object g_scopeType;  // Scope, above

// Set in a spare of a pre-started interpreter once it rehearsed (rehearseInFork): the process
// runs one script, the test's or the fixture's, and ends. Its Scope is then entered at the first
// call and left as it is: there is no other script to hide it from, and leaving and entering
// again around each call (sys.modules copied, compared and restored each time) is work, and
// pages copied, for nothing.
bool g_oneScript = false;

// A script's print() goes to sys.stdout, whose buffer the interpreter empties only at exit, which
// never comes (the interpreter is never finalized; a worker ends with _exit): flushed after each
// call into a script, so what it printed reaches the capture before the test ends, whatever
// PYTHONUNBUFFERED says. Both the current streams and the original ones (a script may have
// replaced sys.stdout). Never throws: the streams are the script's to break (GIL held).
void flushStandardStreams() {
    PyObject* type = nullptr;
    PyObject* value = nullptr;
    PyObject* trace = nullptr;
    PyErr_Fetch(&type, &value, &trace);  // an exception on its way out stays as it was
    for (const char* name : {"stdout", "stderr", "__stdout__", "__stderr__"}) {
        PyObject* stream = PySys_GetObject(name);  // borrowed
        if (stream == nullptr || stream == Py_None) {
            continue;
        }
        PyObject* result = PyObject_CallMethod(stream, "flush", nullptr);
        if (result == nullptr) {
            PyErr_Clear();
        }
        Py_XDECREF(result);
    }
    PyErr_Restore(type, value, trace);
}

// The standard streams write each line as it ends, as they do on a terminal: when a test is
// stopped (its time is up, Ctrl-C) or its thread prints after its call returned, its complete
// lines are in the report already. Only a line not ended yet waits for the next flush.
void writeLinesAsTheyEnd() {
    py::module_ sys = py::module_::import("sys");
    for (const char* name : {"stdout", "stderr"}) {
        py::object stream = py::getattr(sys, name, py::none());
        try {
            if (!stream.is_none() && py::hasattr(stream, "reconfigure")) {
                stream.attr("reconfigure")(py::arg("line_buffering") = true);
            }
        } catch (py::error_already_set&) {
            // A stream that cannot be: its lines wait for the flush after each call.
        }
    }
}

}  // namespace

PYBIND11_EMBEDDED_MODULE(robottestingframework, m) {
    m.doc() = "What Robot Testing Framework test cases and fixtures written in Python call.";
    g_failure =
        PyErr_NewException("robottestingframework.TestFailure", PyExc_BaseException, nullptr);
    g_error = PyErr_NewException("robottestingframework.TestError", PyExc_BaseException, nullptr);
    g_critical = PyErr_NewException("robottestingframework.TestCriticalError", g_error, nullptr);
    // Not Exception subclasses: a script's "except Exception" must not swallow an assertion.
    m.attr("TestFailure") = py::reinterpret_borrow<py::object>(g_failure);
    m.attr("TestError") = py::reinterpret_borrow<py::object>(g_error);
    m.attr("TestCriticalError") = py::reinterpret_borrow<py::object>(g_critical);

    m.def("setName", [](const std::string& name) {
        if (late("setName", TestMessage(name))) {
            return;
        }
        if (g_caller.fixture != nullptr) {
            g_caller.fixture->setName(name);
        } else if (TestCase* test = currentTest()) {
            test->setName(name);
        }
    });
    m.def("testReport", [](const py::object& text) {
        TestMessage message = messageHere(py::str(text));
        if (!late("testReport", message)) {
            report(message);
        }
    });
    m.def("testCheck", [](const py::object& condition, const py::object& text) {
        bool passed = truth(condition);
        if (late(passed ? "testCheck(True)" : "testCheck(False)", messageHere(py::str(text)))) {
            return;
        }
        if (g_caller.fixture != nullptr) {
            if (!passed) {
                report(messageHere(py::str(text), "check failed"));
            }
            return;
        }
        Asserter::testCheck(passed, messageHere(py::str(text)), currentTest());
    });
    // RTF 2.x's meaning, which its tests rely on: the test fails when the condition is false.
    m.def("testFailIf", [](const py::object& condition, const py::object& text) {
        bool passed = truth(condition);
        if (late("testFailIf", messageHere(py::str(text)))) {
            return;
        }
        if (g_caller.fixture != nullptr) {
            if (!passed) {
                report(messageHere(py::str(text), "failed"));
            }
            return;
        }
        Asserter::testFail(passed, messageHere(py::str(text)), currentTest());
    });
    // A number with its unit and optional limits (docs/how-to/measurements-and-attachments.md);
    // outside them the test fails and goes on.
    m.def(
        "testMeasure",
        [](const py::object& name, const py::object& value, const py::object& unit,
           const py::object& low, const py::object& high) {
            Measurement measurement;
            measurement.name = py::str(name);
            measurement.value = number(value);
            measurement.unit = unit.is_none() ? std::string() : std::string(py::str(unit));
            if (!low.is_none()) {
                measurement.low = number(low);
            }
            if (!high.is_none()) {
                measurement.high = number(high);
            }
            if (late("testMeasure", messageHere(describeMeasurement(measurement)))) {
                return;
            }
            if (g_caller.fixture != nullptr) {
                report(messageHere(describeMeasurement(measurement), "measurement"));
                return;
            }
            Asserter::testMeasure(measurement, messageHere(""), currentTest());
        },
        py::arg("name"), py::arg("value"), py::arg("unit") = py::none(),
        py::arg("low") = py::none(), py::arg("high") = py::none());
    // Copies a file into the run's attachments folder
    // (docs/how-to/measurements-and-attachments.md).
    m.def(
        "testAttach",
        [](const py::object& path, const py::object& description) {
            const std::string file = py::str(path);
            const std::string text =
                description.is_none() ? std::string() : std::string(py::str(description));
            if (late("testAttach", messageHere(file))) {
                return;
            }
            if (g_caller.fixture != nullptr) {
                report(messageHere("attachment " + file + " (a fixture attaches nothing)"));
                return;
            }
            Asserter::testAttach(file, text, messageHere(""), currentTest());
        },
        py::arg("path"), py::arg("description") = py::none());
    m.def("assertFail", [](const py::object& text) { raise(g_failure, text); });
    m.def("assertError", [](const py::object& text) { raise(g_error, text); });
    m.def("assertCritical", [](const py::object& text) { raise(g_critical, text); });
    m.def("getEnvironment", []() -> std::string {
        TestCase* test = g_caller.fixture == nullptr ? currentTest() : nullptr;
        return test != nullptr ? test->getEnvironment() : std::string();
    });
    m.def("getParam", []() -> std::string {
        if (g_caller.fixture != nullptr) {
            return g_caller.fixture->getParam();
        }
        TestCase* test = currentTest();
        return test != nullptr ? test->getParam() : std::string();
    });
    // The test whose call runs, as kThreadOwnerSource stamps a thread it starts: (id, name), or
    // None outside a test's call.
    m.def("_running_test", []() -> py::object {
        if (g_caller.test == nullptr || g_caller.fixture != nullptr) {
            return py::none();
        }
        const std::string& key = g_caller.test->getKey();  // its id in its suite (README)
        return py::make_tuple(g_caller.test->getId(), key.empty() ? g_caller.test->getName() : key);
    });
    // For fixture managers: the world is gone; the suite stops running its tests.
    m.def("fixtureCollapsed", [](const py::object& text) {
        if (g_caller.fixture != nullptr && g_caller.fixture->getDispatcher() != nullptr) {
            g_caller.fixture->getDispatcher()->fixtureCollapsed(messageHere(py::str(text)));
        }
    });
}

namespace {

// os._exit() skips everything: in the runner's own process (--isolation none) it would end the
// run with status 0 and no result files. In the process that loaded the interpreter it raises
// SystemExit instead, an error of the test; a forked child still exits at once.
const char* const kExitGuardSource = R"PY(
import os
owner = os.getpid()  # the process the guard is for; a fork of it made by a test exits
def _guard(real=os._exit, getpid=os.getpid):
    def _exit(status):
        if getpid() != owner:
            real(status)
        raise SystemExit("os._exit(%r) was called: it would end the test runner's process "
                         "without a report" % (status,))
    return _exit
os._exit = _guard()
)PY";

// Every thread started while a test's call runs, or by a thread of a test, carries that test
// (endedOwner reads it). Stamped where threading.Thread.start starts its thread, the function of
// _thread it took when it was imported: wrapped here, before any test imports threading, so that
// the pre-started interpreter does not import threading itself. threading registers a hook that
// runs in every fork (its _after_fork: about 0.4 ms of each Python test's process, most of it
// pages copied); a test that uses threads imports it, after the fork. When threading is imported
// already (a sitecustomize did), its own reference is wrapped. Python 3.13 starts threads with
// start_joinable_thread: both names are wrapped where they exist.
const char* const kThreadOwnerSource = R"PY(
import sys
import _thread
import robottestingframework as _rtf
def _stamping(start, modules=sys.modules):
    def start_stamped(function, *args, **kwargs):
        threading = modules.get("threading")
        thread = getattr(function, "__self__", None)
        if threading is not None and isinstance(thread, threading.Thread):
            owner = getattr(threading.current_thread(), "_rtf_test", None)
            if owner is None:
                owner = _rtf._running_test()
            if owner is not None:
                thread._rtf_test = owner
        return start(function, *args, **kwargs)
    return start_stamped
_threading = sys.modules.get("threading")
for _module, _prefix in ((_threading, "_"), (_thread, "")) if _threading else ((_thread, ""),):
    for _name in ("start_new_thread", "start_joinable_thread"):
        if hasattr(_module, _prefix + _name):
            setattr(_module, _prefix + _name, _stamping(getattr(_module, _prefix + _name)))
)PY";

void stampThreads() {
    py::dict globals;
    globals["__builtins__"] = py::module_::import("builtins");
    globals["__name__"] = "_rtf_thread_owner";
    py::exec(kThreadOwnerSource, globals);
}

// The signal that wakes a sleeping script (see wakeScript): a real-time one nobody else uses.
int wakeSignal() {
    return SIGRTMAX - 2;
}
bool g_wakeInstalled = false;

void installWakeHandler() {
    py::dict globals;
    globals["__builtins__"] = py::module_::import("builtins");
    globals["number"] = wakeSignal();
    try {
        py::exec(R"PY(
import signal
def _wake(signum, frame):
    raise KeyboardInterrupt
signal.signal(number, _wake)
)PY",
                 globals);
        g_wakeInstalled = true;
    } catch (py::error_already_set&) {
        // Not the main thread: blocking calls cannot be woken.
    }
}

PyObject* g_exitGuard = nullptr;  // the guard's globals

void guardProcessExit() {
    py::dict globals;
    globals["__builtins__"] = py::module_::import("builtins");
    globals["__name__"] = "_rtf_exit_guard";
    py::exec(kExitGuardSource, globals);
    g_exitGuard = globals.release().ptr();  // never released, like the interpreter
}

// A test that crashes the process natively (a segfault in an extension, ctypes, abort()) gets
// its Python stack, every thread's, written to stderr as the process dies: in a worker that is
// the test's output, which the report keeps beside "crashed: SIGSEGV". The handlers chain to
// the ones before them, so the process still dies of its signal. In the runner's own process
// (--isolation none) the runner dies too; the stack then goes to its stderr.
void dumpStackOnCrash() {
    try {
        py::module_ sys = py::module_::import("sys");
        py::module_::import("faulthandler")
            .attr("enable")(py::arg("file") = sys.attr("__stderr__"),
                            py::arg("all_threads") = true);
    } catch (py::error_already_set&) {
        // No stderr to write to (closed, or not a file): nothing to dump into.
    }
}

// What a test does, on a script of nothing: compile, run it as a module, make its TestCase and
// call it, in its Scope. The first time a process does it, it faults in (and, in a fork, copies)
// the pages it touches; a rehearsal does that ahead of the test (GIL held).
void rehearse() {
    std::string ignored;
    std::unique_ptr<ScriptModule> script = ScriptModule::fromSource(
        "class TestCase:\n    def run(self):\n        pass\n", "/dev/null", ignored);
    if (!script) {
        return;
    }
    ScriptModule::Call call(*script);
    script->attribute("TestCase")().attr("run")();
}

}  // namespace

void ensureInterpreter() {
    static std::once_flag once;
    std::call_once(once, [] {
        if (Py_IsInitialized()) {
            return;  // the host program embeds Python already
        }
        // UTF-8 mode, as python3 itself has under a C or unset locale: print("héllo") and
        // open() use UTF-8 whatever the runner's locale. PYTHONUTF8=0 turns it off.
        PyPreConfig preconfig;
        PyPreConfig_InitIsolatedConfig(&preconfig);  // the locale stays the runner's
        preconfig.isolated = 0;
        preconfig.use_environment = 1;  // as the interpreter's own config below
        const char* utf8 = std::getenv("PYTHONUTF8");
        preconfig.utf8_mode = utf8 != nullptr && std::string(utf8) == "0" ? 0 : 1;
        Py_PreInitialize(&preconfig);
        // No signal handlers: Ctrl-C belongs to the runner.
        py::initialize_interpreter(false, 0, nullptr, false);
        {
            // Keeps test folders free of __pycache__ (tests may live in read-only trees).
            py::module_::import("sys").attr("dont_write_bytecode") = true;
            py::module_::import("robottestingframework");
            py::dict globals;
            globals["__builtins__"] = py::module_::import("builtins");
            globals["__name__"] = "_rtf_scope";
            py::exec(kScopeSource, globals);
            g_scopeType = globals["Scope"];
            g_scopeType.inc_ref();  // never released: the interpreter is never finalized
            addVirtualEnvironment();
            writeLinesAsTheyEnd();
            dumpStackOnCrash();
            guardProcessExit();
            stampThreads();
            installWakeHandler();
        }
        PyEval_SaveThread();  // every later call takes the GIL with gil_scoped_acquire
    });
}

bool prestartInterpreter(std::string& error) {
    try {
        ensureInterpreter();
        // What the interpreter made so far is shared by every fork: the collector leaves it
        // alone, so a test's first collection does not copy every page of it.
        py::gil_scoped_acquire gil;
        // What running a script does the first time (lazy imports, caches) is done once here
        // instead of in every test; so is importing traceback (with re, tokenize...), which only
        // a failing test needs: a test that starts its own interpreter imports it then.
        py::module_::import("traceback");
        rehearse();
        py::module_::import("gc").attr("freeze")();
        return true;
    } catch (const std::exception& e) {
        error = e.what();
        return false;
    }
}

pid_t forkInterpreter() {
    PyGILState_STATE gil = PyGILState_Ensure();
    PyOS_BeforeFork();
    pid_t pid = ::fork();
    if (pid == 0) {
        PyOS_AfterFork_Child();
        // A worker forked from the pre-started interpreter is the process the guard is for.
        if (g_exitGuard != nullptr) {
            PyObject* self = PyLong_FromLong(static_cast<long>(::getpid()));
            PyDict_SetItemString(g_exitGuard, "owner", self);
            Py_XDECREF(self);
        }
    } else {
        PyOS_AfterFork_Parent();
    }
    PyGILState_Release(gil);
    return pid;
}

void rehearseInFork() {
    struct Dedicated {
        ~Dedicated() { g_oneScript = true; }  // after the rehearsal's own script left its Scope
    } dedicated;
    py::gil_scoped_acquire gil;
    try {
        rehearse();
    } catch (const std::exception&) {
        PyErr_Clear();  // nothing of it is kept: the test does its own
    }
}

void wakeScript(unsigned long thread) {
    if (g_wakeInstalled && thread != 0) {
        ::pthread_kill(static_cast<pthread_t>(thread), wakeSignal());
    }
}

CallerScope::CallerScope(Caller caller) : previous_(g_caller) {
    g_caller = caller;
    g_caller.thread = PyThread_get_thread_ident();
}

CallerScope::~CallerScope() {
    g_caller = previous_;
}

void clearPendingAssertion() {
    g_pendingKind = 0;
}

void throwPendingAssertion() {
    int kind = g_pendingKind;
    g_pendingKind = 0;
    if (kind == 1) {
        throw TestFailureException(g_pendingMessage);
    }
    if (kind == 2) {
        throw TestErrorException(g_pendingMessage);
    }
    if (kind == 3) {
        throw TestCriticalErrorException(g_pendingMessage);
    }
}

std::string formatException(py::error_already_set& error) {
    py::module_ traceback = py::module_::import("traceback");
    return trimEnd(
        join(traceback.attr("format_exception")(error.type(), error.value(), error.trace())));
}

void rethrow(py::error_already_set& error) {
    if (error.matches(g_failure) || error.matches(g_error)) {
        TestMessage message;
        py::tuple args = error.value().attr("args");
        if (args.size() == 3) {
            message =
                TestMessage(py::str(args[0]), "", py::str(args[1]), args[2].cast<unsigned int>());
        } else {
            message = TestMessage(py::str(error.value()));
        }
        if (error.matches(g_critical)) {
            throw TestCriticalErrorException(message);
        }
        if (error.matches(g_error)) {
            throw TestErrorException(message);
        }
        throw TestFailureException(message);
    }
    // Anything else: the exception's own line, the traceback, and the innermost frame.
    py::module_ traceback = py::module_::import("traceback");
    TestMessage message(
        trimEnd(join(traceback.attr("format_exception_only")(error.type(), error.value()))),
        formatException(error));
    py::object tb = error.trace();
    while (!tb.is_none() && !tb.attr("tb_next").is_none()) {
        tb = tb.attr("tb_next");
    }
    if (!tb.is_none()) {
        message.setSourceFileName(py::str(tb.attr("tb_frame").attr("f_code").attr("co_filename")));
        message.setSourceLineNumber(tb.attr("tb_lineno").cast<unsigned int>());
    }
    throw TestErrorException(message);
}

std::unique_ptr<ScriptModule> ScriptModule::load(const std::string& path, std::string& error) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        error = "cannot read " + path;
        return nullptr;
    }
    std::stringstream source;
    source << file.rdbuf();
    return fromSource(source.str(), path, error);
}

std::unique_ptr<ScriptModule> ScriptModule::fromSource(const std::string& text,
                                                       const std::string& path,
                                                       std::string& error) {
    static unsigned long counter = 0;
    // compile() would only say "source code string cannot contain null bytes", without where.
    const std::size_t nul = text.find('\0');
    if (nul != std::string::npos) {
        const std::size_t lineStart = text.rfind('\n', nul);
        const std::size_t column = lineStart == std::string::npos ? nul + 1 : nul - lineStart;
        error = path + ":" +
                std::to_string(1 + std::count(text.begin(), text.begin() + nul, '\n')) + ":" +
                std::to_string(column) +
                ": the file holds a NUL byte, which Python source cannot (a binary file, or text "
                "saved as UTF-16?)";
        return nullptr;
    }

    // A pre-started interpreter read its environment before the worker was asked for: the
    // variables set since (a suite's resource items, RTF_RESOURCE_<POOL>) reach os.environ too.
    py::object environment = py::module_::import("os").attr("environ");
    for (char** entry = environ; *entry != nullptr; ++entry) {
        const std::string variable = *entry;
        const std::size_t equals = variable.find('=');
        if (variable.compare(0, 13, "RTF_RESOURCE_") == 0 && equals != std::string::npos) {
            environment[py::str(variable.substr(0, equals))] = py::str(variable.substr(equals + 1));
        }
    }

    py::module_ builtins = py::module_::import("builtins");
    py::object code;
    try {
        code = builtins.attr("compile")(py::bytes(text), path, "exec", 0, true);
    } catch (py::error_already_set& e) {
        if (e.matches(PyExc_SyntaxError)) {
            py::object value = e.value();
            std::string where = py::str(value.attr("filename")).cast<std::string>() + ":" +
                                py::str(value.attr("lineno")).cast<std::string>() + ":" +
                                py::str(value.attr("offset")).cast<std::string>();
            py::module_ traceback = py::module_::import("traceback");
            error = "syntax error at " + where + "\n" +
                    trimEnd(join(traceback.attr("format_exception_only")(e.type(), value)));
        } else {
            error = formatException(e);
        }
        return nullptr;
    }

    std::unique_ptr<ScriptModule> script(new ScriptModule);
    std::string stem = std::filesystem::path(path).stem().string();
    for (char& c : stem) {
        if (!std::isalnum(static_cast<unsigned char>(c))) {
            c = '_';
        }
    }
    std::string name = "_rtf_script_" + std::to_string(++counter) + "_" + stem;
    std::string folder = std::filesystem::absolute(path).parent_path().lexically_normal().string();
    script->module_ = py::module_::import("types").attr("ModuleType")(name);
    script->module_.attr("__file__") = path;
    script->module_.attr("__builtins__") = builtins;
    // RTF 2.x put the module in every test's namespace; its tests call it without an import.
    script->module_.attr("robottestingframework") = py::module_::import("robottestingframework");
    script->scope_ = g_scopeType(folder, name, script->module_);
    try {
        Call call(*script);
        builtins.attr("exec")(code, script->module_.attr("__dict__"));
    } catch (py::error_already_set& e) {
        error = formatException(e);
        return nullptr;
    }
    return script;
}

ScriptModule::~ScriptModule() {
    py::gil_scoped_acquire gil;
    scope_ = py::object();
    module_ = py::object();
}

ScriptModule::Call::Call(ScriptModule& script) : script_(script) {
    if (!g_oneScript || !script_.entered_) {
        script_.scope_.attr("enter")();
        script_.entered_ = true;
    }
}

ScriptModule::Call::~Call() {
    // Never throws: a script may have messed sys.path or sys.modules up.
    if (!g_oneScript) {
        try {
            script_.scope_.attr("leave")();
        } catch (py::error_already_set&) {
            PyErr_Clear();
        }
        script_.entered_ = false;
    }
    flushStandardStreams();
}

py::object ScriptModule::attribute(const char* name) const {
    return py::getattr(module_, name, py::none());
}

}  // namespace python
}  // namespace languages
}  // namespace robottestingframework
