// Ruby 3 test cases: the file defines class TestCase (setup(param), run, tearDown); module
// RobotTestingFramework holds what the script can call. Each file is loaded under a fresh
// anonymous module, so two tests' classes and top-level methods never meet.
#include <ruby.h>
#include <ruby/encoding.h>
#include <unistd.h>

#include <string>

#include <robottestingframework/Asserter.h>
#include <robottestingframework/Exception.h>

#include "languages/language_loaders.h"
#include "languages/ruby/ruby_vm.h"
#include "languages/script_module_interface.h"

namespace robottestingframework {
namespace languages {

namespace {

enum class Stop { None, Failure, Error, Critical };

// Set on the Ruby thread only.
VALUE g_failure = Qnil;   // RobotTestingFramework::TestFailure
VALUE g_error = Qnil;     // RobotTestingFramework::TestError
VALUE g_critical = Qnil;  // RobotTestingFramework::TestCriticalError

class RubyTestCase;
RubyTestCase* g_active = nullptr;  // whose script is running

std::string toString(VALUE value) {
    VALUE text = rb_obj_as_string(value);
    return std::string(RSTRING_PTR(text), static_cast<std::size_t>(RSTRING_LEN(text)));
}

TestMessage messageHere(const std::string& text) {
    const char* file = rb_sourcefile();
    return TestMessage(text, "", file ? file : "", static_cast<unsigned int>(rb_sourceline()));
}

// Calls `body` under rb_protect; returns the exception it raised, or Qnil.
template <typename Body>
VALUE protect(Body body) {
    int state = 0;
    rb_protect(
        [](VALUE data) -> VALUE {
            (*reinterpret_cast<Body*>(data))();
            return Qnil;
        },
        reinterpret_cast<VALUE>(&body), &state);
    if (state == 0) {
        return Qnil;
    }
    VALUE error = rb_errinfo();
    rb_set_errinfo(Qnil);
    return NIL_P(error) ? rb_exc_new_cstr(rb_eRuntimeError, "unknown Ruby error") : error;
}

// Ruby buffers $stdout when it is not a terminal and the VM never exits: what a script printed
// is pushed out at the end of each call, so it reaches the report of the phase that printed it.
void flushOutput() {
    protect([] {
        for (const char* name : {"$stdout", "$stderr"}) {
            VALUE stream = rb_gv_get(name);
            if (rb_respond_to(stream, rb_intern("flush"))) {
                rb_funcall(stream, rb_intern("flush"), 0);
            }
        }
    });
}

// How Ruby itself prints the exception: message, class and backtrace.
std::string describe(VALUE error) {
    std::string text;
    if (RTEST(rb_obj_is_kind_of(error, rb_eSyntaxError))) {
        // Its message says where (file:line: ...); its backtrace would only name the loader.
        protect([&] { text = toString(rb_funcall(error, rb_intern("message"), 0)); });
        return text + " (SyntaxError)";
    }
    VALUE failed = protect([&] {
        VALUE options = rb_hash_new();
        rb_hash_aset(options, ID2SYM(rb_intern("highlight")), Qfalse);
        rb_hash_aset(options, ID2SYM(rb_intern("order")), ID2SYM(rb_intern("top")));
        text = toString(
            rb_funcallv_kw(error, rb_intern("full_message"), 1, &options, RB_PASS_KEYWORDS));
    });
    if (!NIL_P(failed)) {
        text = std::string(rb_obj_classname(error));
    }
    while (!text.empty() && text.back() == '\n') {
        text.pop_back();
    }
    return text;
}

class RubyTestCase : public TestCase {
public:
    explicit RubyTestCase(const std::string& path) : TestCase(path), path_(path) {}

    ~RubyTestCase() override {
        RubyVm::run([this] {
            if (registered_) {
                rb_gc_unregister_address(&instance_);
                rb_gc_unregister_address(&module_);
            }
        });
    }

    bool load(std::string& error) {
        bool ok = false;
        RubyVm::run([&] {
            rb_gc_register_address(&instance_);
            rb_gc_register_address(&module_);
            registered_ = true;
            Active active(this);
            module_ = rb_module_new();
            VALUE raised = protect([&] {
                rb_funcall(rb_mKernel, rb_intern("load"), 2, rb_str_new_cstr(path_.c_str()),
                           module_);
            });
            flushOutput();
            if (!NIL_P(raised)) {
                error = describe(raised);
                return;
            }
            ID name = rb_intern("TestCase");
            if (!rb_const_defined_at(module_, name)) {
                error = path_ + " defines no class TestCase";
                return;
            }
            raised = protect([&] {
                VALUE type = rb_const_get_at(module_, name);
                // The file's top-level methods live in its module: its class sees them.
                if (RB_TYPE_P(type, T_CLASS)) {
                    rb_include_module(type, module_);
                }
                instance_ = rb_class_new_instance(0, nullptr, type);
            });
            if (!NIL_P(raised)) {
                error = describe(raised);
                return;
            }
            if (!rb_respond_to(instance_, rb_intern("run"))) {
                error = "class TestCase of " + path_ + " has no run method";
                return;
            }
            ok = true;
        });
        return ok;
    }

    bool setup(int /*argc*/, char** /*argv*/) override {
        bool ok = true;
        call("setup", [&](ID method) {
            VALUE param = rb_utf8_str_new_cstr(getParam().c_str());
            VALUE answer = rb_funcall(instance_, method, 1, param);
            ok = NIL_P(answer) || RTEST(answer);  // nothing returned: success
        });
        return ok;
    }

    void run() override {
        call("run", [&](ID method) { rb_funcall(instance_, method, 0); });
    }

    void tearDown() override {
        call("tearDown", [&](ID method) { rb_funcall(instance_, method, 0); });
    }

    void stop(Stop kind, const TestMessage& message) {
        stop_ = kind;
        stopMessage_ = message;
    }

private:
    struct Active {
        explicit Active(RubyTestCase* test) : previous(g_active) { g_active = test; }
        ~Active() { g_active = previous; }
        RubyTestCase* previous;
    };

    // Calls the instance's method `name` (when it has one) through `body`, on the Ruby thread.
    template <typename Body>
    void call(const char* name, Body body) {
        RubyVm::run([&] {
            ID method = rb_intern(name);
            if (!rb_respond_to(instance_, method)) {
                return;
            }
            Active active(this);
            stop_ = Stop::None;
            VALUE raised = protect([&] { body(method); });
            flushOutput();
            // An assertion counts even when the script rescued it.
            if (stop_ != Stop::None &&
                (NIL_P(raised) || RTEST(rb_obj_is_kind_of(raised, g_failure)) ||
                 RTEST(rb_obj_is_kind_of(raised, g_error)))) {
                if (stop_ == Stop::Failure) {
                    throw TestFailureException(stopMessage_);
                }
                if (stop_ == Stop::Critical) {
                    throw TestCriticalErrorException(stopMessage_);
                }
                throw TestErrorException(stopMessage_);
            }
            if (NIL_P(raised)) {
                return;
            }
            std::string message = toString(rb_funcall(raised, rb_intern("message"), 0)) + " (" +
                                  rb_obj_classname(raised) + ")";
            TestMessage error(message, describe(raised));
            VALUE locations = rb_funcall(raised, rb_intern("backtrace_locations"), 0);
            if (RB_TYPE_P(locations, T_ARRAY) && RARRAY_LEN(locations) > 0) {
                VALUE top = rb_ary_entry(locations, 0);
                error.setSourceFileName(toString(rb_funcall(top, rb_intern("path"), 0)));
                error.setSourceLineNumber(NUM2UINT(rb_funcall(top, rb_intern("lineno"), 0)));
            }
            throw TestErrorException(error);
        });
    }

    std::string path_;
    VALUE module_ = Qnil;
    VALUE instance_ = Qnil;
    bool registered_ = false;
    Stop stop_ = Stop::None;
    TestMessage stopMessage_;
};

TestCase* activeTest() {
    return g_active != nullptr ? static_cast<TestCase*>(g_active) : TestCase::current();
}

// Raises `type`: the test remembers the message (with the script's file:line) for the wrapper.
VALUE raise(VALUE type, VALUE text, Stop kind) {
    VALUE message = rb_obj_as_string(text);
    if (g_active != nullptr) {
        g_active->stop(kind, messageHere(toString(message)));
    }
    rb_exc_raise(rb_exc_new_str(type, message));
    return Qnil;
}

VALUE setName(VALUE, VALUE name) {
    VALUE text = rb_obj_as_string(name);
    if (TestCase* test = activeTest()) {
        test->setName(toString(text));
    }
    return Qnil;
}

VALUE testReport(VALUE, VALUE text) {
    VALUE message = rb_obj_as_string(text);
    Asserter::report(messageHere(toString(message)), activeTest());
    return Qnil;
}

VALUE testCheck(VALUE, VALUE condition, VALUE text) {
    VALUE message = rb_obj_as_string(text);
    Asserter::testCheck(RTEST(condition), messageHere(toString(message)), activeTest());
    return Qnil;
}

// RTF 2.x's meaning, which its tests rely on: the test fails when the condition is false.
VALUE testFailIf(VALUE, VALUE condition, VALUE text) {
    VALUE message = rb_obj_as_string(text);
    Asserter::testFail(RTEST(condition), messageHere(toString(message)), activeTest());
    return Qnil;
}

// testMeasure(name, value, unit = nil, low = nil, high = nil). Ruby raises by longjmp: every
// argument is converted before a C++ object with a destructor exists.
VALUE testMeasure(int argc, VALUE* argv, VALUE) {
    VALUE name, value, unit, low, high;
    rb_scan_args(argc, argv, "23", &name, &value, &unit, &low, &high);
    VALUE nameText = rb_obj_as_string(name);
    const double number = NUM2DBL(value);
    VALUE unitText = NIL_P(unit) ? rb_str_new_cstr("") : rb_obj_as_string(unit);
    const double lowNumber = NIL_P(low) ? 0 : NUM2DBL(low);
    const double highNumber = NIL_P(high) ? 0 : NUM2DBL(high);
    Measurement measurement;
    measurement.name = toString(nameText);
    measurement.value = number;
    measurement.unit = toString(unitText);
    if (!NIL_P(low)) {
        measurement.low = lowNumber;
    }
    if (!NIL_P(high)) {
        measurement.high = highNumber;
    }
    Asserter::testMeasure(measurement, messageHere(""), activeTest());
    return Qnil;
}

VALUE testAttach(int argc, VALUE* argv, VALUE) {
    VALUE path, description;
    rb_scan_args(argc, argv, "11", &path, &description);
    VALUE pathText = rb_obj_as_string(path);
    VALUE descriptionText =
        NIL_P(description) ? rb_str_new_cstr("") : rb_obj_as_string(description);
    Asserter::testAttach(toString(pathText), toString(descriptionText), messageHere(""),
                         activeTest());
    return Qnil;
}

VALUE assertFail(VALUE, VALUE text) {
    return raise(g_failure, text, Stop::Failure);
}

VALUE assertError(VALUE, VALUE text) {
    return raise(g_error, text, Stop::Error);
}

VALUE assertCritical(VALUE, VALUE text) {
    return raise(g_critical, text, Stop::Critical);
}

VALUE getEnvironment(VALUE) {
    TestCase* test = activeTest();
    return rb_utf8_str_new_cstr(test ? test->getEnvironment().c_str() : "");
}

VALUE getParam(VALUE) {
    TestCase* test = activeTest();
    return rb_utf8_str_new_cstr(test ? test->getParam().c_str() : "");
}

class LoadedRubyTest : public LoadedTest {
public:
    explicit LoadedRubyTest(std::unique_ptr<RubyTestCase> test) : test_(std::move(test)) {}
    TestCase* get() override { return test_.get(); }

private:
    std::unique_ptr<RubyTestCase> test_;
};

}  // namespace

// Called once, on the Ruby thread, right after the VM started.
void defineRubyModule() {
    VALUE module = rb_define_module("RobotTestingFramework");
    // Not StandardError: a script's bare "rescue" must not swallow an assertion.
    g_failure = rb_define_class_under(module, "TestFailure", rb_eException);
    g_error = rb_define_class_under(module, "TestError", rb_eException);
    g_critical = rb_define_class_under(module, "TestCriticalError", g_error);
    using Function = VALUE (*)(ANYARGS);
    rb_define_module_function(module, "setName", reinterpret_cast<Function>(setName), 1);
    rb_define_module_function(module, "testReport", reinterpret_cast<Function>(testReport), 1);
    rb_define_module_function(module, "testCheck", reinterpret_cast<Function>(testCheck), 2);
    rb_define_module_function(module, "testFailIf", reinterpret_cast<Function>(testFailIf), 2);
    rb_define_module_function(module, "testMeasure", reinterpret_cast<Function>(testMeasure), -1);
    rb_define_module_function(module, "testAttach", reinterpret_cast<Function>(testAttach), -1);
    rb_define_module_function(module, "assertFail", reinterpret_cast<Function>(assertFail), 1);
    rb_define_module_function(module, "assertError", reinterpret_cast<Function>(assertError), 1);
    rb_define_module_function(module, "assertCritical", reinterpret_cast<Function>(assertCritical),
                              1);
    rb_define_module_function(module, "getEnvironment", reinterpret_cast<Function>(getEnvironment),
                              0);
    rb_define_module_function(module, "getParam", reinterpret_cast<Function>(getParam), 0);
    // exit! skips everything: in the runner's own process (--isolation none) it would end the
    // run with status 0 and no result files. In this process it raises SystemExit instead, an
    // error of the test; a forked child still exits at once.
    rb_eval_string(R"RUBY(
module RobotTestingFramework
  PROCESS_ID = Process.pid
end
module Process
  class << self
    alias_method :__rtf_exit!, :exit!
    def exit!(status = false)
      __rtf_exit!(status) unless Process.pid == RobotTestingFramework::PROCESS_ID
      raise SystemExit.new(false, "exit!(#{status.inspect}) was called: it would end the " \
                                  "test runner's process without a report")
    end
  end
end
module Kernel
  private def exit!(status = false) = Process.exit!(status)
end
# Rubygems (left out at start, as it would cost every test) comes with the first require that
# does not find its file: it then looks among the installed gems, as with ruby.
module Kernel
  alias_method :__rtf_require_without_gems, :require
  private def require(path)
    __rtf_require_without_gems(path)
  rescue LoadError
    raise if defined?(::Gem)
    __rtf_require_without_gems("rubygems")
    require(path)
  end
end
)RUBY");
}

std::unique_ptr<LoadedTest> loadRubyTest(const std::string& path, std::string& error) {
    auto test = std::make_unique<RubyTestCase>(path);
    try {
        if (!test->load(error)) {
            return nullptr;
        }
    } catch (const std::exception& e) {
        error = e.what();
        return nullptr;
    }
    return std::make_unique<LoadedRubyTest>(std::move(test));
}

}  // namespace languages
}  // namespace robottestingframework

namespace robottestingframework {
namespace languages {

// What a test does, on a script of nothing: its code compiled in a module of its own, its
// TestCase made and called, the output flushed; done once by the pre-started VM, so that what
// Ruby does the first time is not done again in every fork.
namespace {
void rehearse() {
    protect([] {
        VALUE module = rb_module_new();
        rb_funcall(module, rb_intern("module_eval"), 3,
                   rb_str_new_cstr("class TestCase\n  def run\n  end\nend\n"),
                   rb_str_new_cstr("/dev/null"), INT2FIX(1));
        VALUE type = rb_const_get_at(module, rb_intern("TestCase"));
        rb_include_module(type, module);
        VALUE instance = rb_class_new_instance(0, nullptr, type);
        if (rb_respond_to(instance, rb_intern("run"))) {
            rb_funcall(instance, rb_intern("run"), 0);
        }
    });
    flushOutput();
}
}  // namespace

// The pre-started VM: its thread (ruby_vm.h) runs the fork server's loop and forks each
// worker, so a worker's only thread is the one Ruby knows. The process's first thread only
// waits for it, and is not in any worker.
bool prestartRuby(std::string& error) {
    try {
        RubyVm::start();
        // What running a script does the first time is done once here, not in every test.
        RubyVm::run([] { rehearse(); });
        return true;
    } catch (const std::exception& e) {
        error = e.what();
        return false;
    }
}

pid_t forkRuby() {
    pid_t pid = RubyVm::fork();
    if (pid == 0) {
        RubyVm::run([] {
            // A worker is the process exit! must not end (see the guard above); set from C, as
            // compiling Ruby code here would cost every test.
            protect([] {
                VALUE module = rb_const_get(rb_cObject, rb_intern("RobotTestingFramework"));
                ID name = rb_intern("PROCESS_ID");
                rb_const_remove(module, name);
                rb_const_set(module, name, PIDT2NUM(::getpid()));
            });
        });
    }
    return pid;
}

int hostRuby(int (*serve)(void*), void* context) {
    int code = 0;
    RubyVm::run([&] { code = serve(context); });
    return code;
}

}  // namespace languages
}  // namespace robottestingframework

// The module's entry point: what test_loader.cpp finds with dlsym.
const robottestingframework::languages::LanguageModule* rtf_language_module() {
    static const robottestingframework::languages::LanguageModule module{
        robottestingframework::languages::kLanguageModuleVersion,
        robottestingframework::languages::loadRubyTest,
        nullptr,
        robottestingframework::languages::prestartRuby,
        robottestingframework::languages::forkRuby,
        robottestingframework::languages::hostRuby,
        nullptr};  // a Ruby test loads little: rehearsing it in each spare cost more than it saved
    return &module;
}
