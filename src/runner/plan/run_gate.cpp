#include "runner/plan/run_gate.h"

#include <algorithm>

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

bool dependencyNames(const std::string& dependency, const TestSpec& spec) {
    return names(dependency, spec);
}

std::string findUnknownDependency(const std::vector<SuiteSpec>& suites) {
    for (const auto& suite : suites) {
        for (const auto& test : suite.tests) {
            for (const auto& dependency : test.depends) {
                bool known = false;
                for (const auto& other : suites) {
                    for (const auto& candidate : other.tests) {
                        // Itself included: a test that depends on itself is a cycle, said so
                        // by findDependencyCycle.
                        known = known || names(dependency, candidate);
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

namespace {

std::string label(const TestSpec& test) {
    const std::string& name = (test.name.empty() ? test.plugin : test.name).str();
    return name + " (" + test.where.toString() + ")";
}

// Finds a cycle among the tests' dependencies by a depth-first walk.
class CycleFinder {
public:
    explicit CycleFinder(const std::vector<SuiteSpec>& suites) {
        for (const auto& suite : suites) {
            for (const auto& test : suite.tests) {
                tests_.push_back(&test);
            }
        }
        // A dependency means the other tests it names, as the gate reads it; itself only when
        // it names no other.
        edges_.resize(tests_.size());
        for (std::size_t i = 0; i < tests_.size(); ++i) {
            for (const auto& dependency : tests_[i]->depends) {
                bool other = false;
                for (std::size_t j = 0; j < tests_.size(); ++j) {
                    if (j != i && names(dependency, *tests_[j])) {
                        edges_[i].push_back(j);
                        other = true;
                    }
                }
                if (!other && names(dependency, *tests_[i])) {
                    edges_[i].push_back(i);
                }
            }
        }
    }

    std::string find() {
        state_.assign(tests_.size(), State::New);
        for (std::size_t i = 0; i < tests_.size(); ++i) {
            if (state_[i] == State::New && visit(i)) {
                return describe();
            }
        }
        return {};
    }

private:
    enum class State { New, OnPath, Done };

    // True when a cycle was found: then path_ ends with it, from its first test.
    bool visit(std::size_t i) {
        state_[i] = State::OnPath;
        path_.push_back(i);
        for (std::size_t next : edges_[i]) {
            if (state_[next] == State::OnPath) {
                path_.erase(path_.begin(), std::find(path_.begin(), path_.end(), next));
                return true;
            }
            if (state_[next] == State::New && visit(next)) {
                return true;
            }
        }
        path_.pop_back();
        state_[i] = State::Done;
        return false;
    }

    std::string describe() const {
        const TestSpec& first = *tests_[path_.front()];
        if (path_.size() == 1) {
            return first.where.toString() + ": dependency cycle: " + label(first) +
                   " depends on itself";
        }
        std::string text = first.where.toString() + ": dependency cycle: " + label(first);
        for (std::size_t k = 1; k < path_.size(); ++k) {
            text += " depends on " + label(*tests_[path_[k]]) + ", which";
        }
        return text + " depends on " + label(first);
    }

    std::vector<const TestSpec*> tests_;
    std::vector<std::vector<std::size_t>> edges_;
    std::vector<State> state_;
    std::vector<std::size_t> path_;
};

}  // namespace

std::string findDependencyCycle(const std::vector<SuiteSpec>& suites) {
    return CycleFinder(suites).find();
}

void RunGate::tripped(const Test* test) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (firstFailure_.empty()) {
        firstFailure_ = test != nullptr && !test->getName().empty() ? test->getName() : "a test";
        firstFailing_ = test;
    }
}

void RunGate::onEvent(const RunEvent& event) {
    if (!tripsFailFast(event.data.kind)) {
        return;
    }
    // A failing kind trips the gate; the retry that follows a failed attempt takes it back.
    if (isFailure(stateOf(event.data.kind))) {
        tripped(event.test);
    } else {
        retried(event.test);
    }
}

void RunGate::retried(const Test* test) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (test != nullptr && firstFailing_ == test) {
        firstFailure_.clear();
        firstFailing_ = nullptr;
    }
}

bool RunGate::skip(const Test* test, TestMessage& reason) {
    if (failFast_) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!firstFailure_.empty()) {
            reason = TestMessage("--fail-fast, " + firstFailure_ + " failed");
            return true;
        }
    }
    const auto* self = dynamic_cast<const PluginTest*>(test);
    if (self == nullptr) {
        return false;  // a suite
    }
    if (!self->spec().skipReason.empty()) {
        reason = TestMessage(self->spec().skipReason);  // decided before the run (selection)
        return true;
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
            if (other.status() != TestStatus::Passed && other.status() != TestStatus::Flaky) {
                reason = TestMessage(
                    "depends on " + dependency + ", which " +
                    (other.status() == TestStatus::Skipped
                         ? std::string("was skipped")
                         : std::string("did not pass (") + toString(other.status()) + ")"));
                return true;
            }
        }
        if (!ran) {
            reason = TestMessage("depends on " + dependency + ", which did not run");
            return true;
        }
    }
    return false;
}

}  // namespace runner
}  // namespace robottestingframework
