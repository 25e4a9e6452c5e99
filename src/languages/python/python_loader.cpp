// Python test cases (class TestCase) and fixture managers (class FixtureManager) as the
// framework's objects: each call into the script takes the GIL and turns Python exceptions into
// the framework's.
#include <atomic>

#include <robottestingframework/Asserter.h>
#include <robottestingframework/Exception.h>

#include "languages/language_loaders.h"
#include "languages/python/python_runtime.h"
#include "languages/script_module_interface.h"

namespace robottestingframework {
namespace languages {

using namespace python;

namespace {

// The script's answer to setup(): nothing returned counts as success, False as failure.
bool setupAnswer(const py::object& answer) {
    if (answer.is_none()) {
        return true;
    }
    int truth = PyObject_IsTrue(answer.ptr());
    if (truth < 0) {
        throw py::error_already_set();
    }
    return truth != 0;
}

// Makes the instance of the script's class `className`; nullptr-equivalent (None) and `error`
// set on failure.
py::object instantiate(ScriptModule& script, const char* className, const std::string& path,
                       std::string& error) {
    py::object type = script.attribute(className);
    if (type.is_none() || !PyType_Check(type.ptr())) {
        error = path + " defines no class " + className;
        return py::none();
    }
    try {
        return type();
    } catch (py::error_already_set& e) {
        error = formatException(e);
        return py::none();
    }
}

class PythonTestCase : public TestCase {
public:
    PythonTestCase(const std::string& path, std::unique_ptr<ScriptModule> script)
        : TestCase(path), script_(std::move(script)) {}

    ~PythonTestCase() override {
        py::gil_scoped_acquire gil;
        instance_ = py::object();
        script_.reset();
    }

    bool create(const std::string& path, std::string& error) {
        CallerScope caller({this, nullptr});
        ScriptModule::Call scope(*script_);
        instance_ = instantiate(*script_, "TestCase", path, error);
        if (instance_.is_none()) {
            return false;
        }
        if (!py::hasattr(instance_, "run")) {
            error = "class TestCase of " + path + " has no run() method";
            return false;
        }
        return true;
    }

    bool setup(int /*argc*/, char** /*argv*/) override {
        bool ok = true;
        call("setup", [&](const py::object& method) { ok = setupAnswer(method(getParam())); });
        return ok;
    }

    void run() override {
        call("run", [](const py::object& method) { method(); });
    }

    void tearDown() override {
        call("tearDown", [](const py::object& method) { method(); });
    }

    void interrupt() override {
        TestCase::interrupt();
        unsigned long thread = thread_;
        if (thread != 0) {
            // Raised in the script at its next bytecode: stops loops, not blocking C calls.
            py::gil_scoped_acquire gil;
            PyThreadState_SetAsyncExc(thread, PyExc_KeyboardInterrupt);
            wakeScript(thread);  // out of time.sleep() and other blocking calls
        }
    }

private:
    // Calls the instance's method `name` (when it has one) through `body`.
    template <typename Body>
    void call(const char* name, Body body) {
        py::gil_scoped_acquire gil;
        CallerScope caller({this, nullptr});
        try {
            ScriptModule::Call scope(*script_);
            py::object method = py::getattr(instance_, name, py::none());
            if (method.is_none()) {
                return;
            }
            thread_ = PyThread_get_thread_ident();
            clearPendingAssertion();
            body(method);
            thread_ = 0;
            throwPendingAssertion();  // an assertion the script caught still counts
        } catch (py::error_already_set& e) {
            thread_ = 0;
            rethrow(e);
        }
    }

    std::unique_ptr<ScriptModule> script_;
    py::object instance_;
    std::atomic<unsigned long> thread_{0};
};

class PythonFixture : public FixtureManager {
public:
    explicit PythonFixture(std::unique_ptr<ScriptModule> script) : script_(std::move(script)) {}

    ~PythonFixture() override {
        py::gil_scoped_acquire gil;
        instance_ = py::object();
        script_.reset();
    }

    bool create(const std::string& path, std::string& error) {
        CallerScope caller({nullptr, this});
        ScriptModule::Call scope(*script_);
        instance_ = instantiate(*script_, "FixtureManager", path, error);
        return !instance_.is_none();
    }

    bool setup(int /*argc*/, char** /*argv*/) override {
        bool ok = true;
        call("setup", [&](const py::object& method) { ok = setupAnswer(method(getParam())); });
        return ok;
    }

    bool check() override {
        bool ok = true;
        call("check", [&](const py::object& method) { ok = setupAnswer(method()); });
        return ok;
    }

    void tearDown() override {
        call("tearDown", [](const py::object& method) { method(); });
    }

private:
    // A fixture's exception is reported with its traceback and thrown on with its own line,
    // so the suite fails (a tearDown too) and tells the tests it skips why.
    template <typename Body>
    void call(const char* name, Body body) {
        py::gil_scoped_acquire gil;
        CallerScope caller({nullptr, this});
        try {
            ScriptModule::Call scope(*script_);
            py::object method = py::getattr(instance_, name, py::none());
            if (!method.is_none()) {
                body(method);
            }
        } catch (py::error_already_set& e) {
            try {
                rethrow(e);
            } catch (const Exception& converted) {
                const TestMessage& message = converted.message();
                if (!message.getDetail().empty()) {
                    Asserter::report(message, this);
                }
                throw TestErrorException(TestMessage(message.getMessage(), "",
                                                     message.getSourceFileName(),
                                                     message.getSourceLineNumber()));
            }
        }
    }

    std::unique_ptr<ScriptModule> script_;
    py::object instance_;
};

class LoadedPythonTest : public LoadedTest {
public:
    explicit LoadedPythonTest(std::unique_ptr<PythonTestCase> test) : test_(std::move(test)) {}
    TestCase* get() override { return test_.get(); }

private:
    std::unique_ptr<PythonTestCase> test_;
};

class LoadedPythonFixture : public LoadedFixture {
public:
    explicit LoadedPythonFixture(std::unique_ptr<PythonFixture> fixture)
        : fixture_(std::move(fixture)) {}
    FixtureManager* get() override { return fixture_.get(); }

private:
    std::unique_ptr<PythonFixture> fixture_;
};

}  // namespace

std::unique_ptr<LoadedTest> loadPythonTest(const std::string& path, std::string& error) {
    ensureInterpreter();
    py::gil_scoped_acquire gil;
    std::unique_ptr<ScriptModule> script = ScriptModule::load(path, error);
    if (!script) {
        return nullptr;
    }
    auto test = std::make_unique<PythonTestCase>(path, std::move(script));
    if (!test->create(path, error)) {
        return nullptr;
    }
    return std::make_unique<LoadedPythonTest>(std::move(test));
}

std::unique_ptr<LoadedFixture> loadPythonFixture(const std::string& path, std::string& error) {
    ensureInterpreter();
    py::gil_scoped_acquire gil;
    std::unique_ptr<ScriptModule> script = ScriptModule::load(path, error);
    if (!script) {
        return nullptr;
    }
    auto fixture = std::make_unique<PythonFixture>(std::move(script));
    if (!fixture->create(path, error)) {
        return nullptr;
    }
    fixture->setName(path);
    return std::make_unique<LoadedPythonFixture>(std::move(fixture));
}

}  // namespace languages
}  // namespace robottestingframework

// The module's entry point: what test_loader.cpp finds with dlsym.
const robottestingframework::languages::LanguageModule* rtf_language_module() {
    static const robottestingframework::languages::LanguageModule module{
        robottestingframework::languages::kLanguageModuleVersion,
        robottestingframework::languages::loadPythonTest,
        robottestingframework::languages::loadPythonFixture,
        robottestingframework::languages::python::prestartInterpreter,
        robottestingframework::languages::python::forkInterpreter,
        nullptr,
        robottestingframework::languages::python::rehearseInFork};
    return &module;
}
