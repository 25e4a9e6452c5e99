#include "run_gate.h"

namespace robottestingframework {
namespace runner {

namespace {

std::string baseName(const std::string& path) {
    std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// "libfoo.so" and "foo.py" → "foo": how a plug-in is often named without its file name.
std::string stem(const std::string& path) {
    std::string name = baseName(path);
    std::size_t dot = name.find('.');
    if (dot != std::string::npos && dot > 0) {
        name = name.substr(0, dot);
    }
    if (name.size() > 3 && name.compare(0, 3, "lib") == 0) {
        name = name.substr(3);
    }
    return name;
}

// Whether `dependency` names `spec` before it runs.
bool names(const std::string& dependency, const TestSpec& spec) {
    return dependency == spec.name || dependency == spec.plugin ||
           dependency == baseName(spec.plugin) || dependency == stem(spec.plugin);
}

}  // namespace

std::string findUnknownDependency(const std::vector<SuiteSpec>& suites) {
    for (const auto& suite : suites) {
        for (const auto& test : suite.tests) {
            for (const auto& dependency : test.depends) {
                bool known = false;
                for (const auto& other : suites) {
                    for (const auto& candidate : other.tests) {
                        known = known || (&candidate != &test && names(dependency, candidate));
                    }
                }
                if (!known) {
                    return test.where.toString() + ": unknown dependency '" + dependency +
                           "': no other test of the run has that name or plug-in";
                }
            }
        }
    }
    return {};
}

void RunGate::tripped(const Test* test) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (firstFailure_.empty()) {
        firstFailure_ = test != nullptr && !test->getName().empty() ? test->getName() : "a test";
    }
}

bool RunGate::skip(const Test* test, TestMessage& reason) {
    if (failFast_) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!firstFailure_.empty()) {
            reason = TestMessage("skipped: --fail-fast, " + firstFailure_ + " failed");
            return true;
        }
    }
    const auto* self = dynamic_cast<const PluginTest*>(test);
    if (self == nullptr) {
        return false;  // a suite
    }
    for (const auto& dependency : self->spec().depends) {
        bool ran = false;
        for (const auto& other : tests_) {
            if (&other == self) {
                continue;
            }
            const bool named =
                names(dependency, other.spec()) || (other.ran() && dependency == other.getName());
            if (!named) {
                continue;
            }
            if (!other.ran()) {
                continue;  // not yet run, or skipped before running: looked at below
            }
            ran = true;
            if (other.status() != TestStatus::Passed) {
                reason = TestMessage(
                    "skipped: depends on " + dependency + ", which " +
                    (other.status() == TestStatus::Skipped
                         ? std::string("was skipped")
                         : std::string("did not pass (") + toString(other.status()) + ")"));
                return true;
            }
        }
        if (!ran) {
            reason = TestMessage("skipped: depends on " + dependency + ", which did not run");
            return true;
        }
    }
    return false;
}

}  // namespace runner
}  // namespace robottestingframework
