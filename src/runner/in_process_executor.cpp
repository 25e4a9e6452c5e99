#include "in_process_executor.h"

#include <robottestingframework/TestResult.h>
#include <robottestingframework/dll/DllPluginLoader.h>

#include <algorithm>
#include <exception>

#include "plugin_test.h"

namespace robottestingframework {
namespace runner {

namespace {

std::string folderOf(const std::string& file) {
    std::size_t slash = file.rfind('/');
    if (file.empty() || slash == std::string::npos) {
        return ".";
    }
    return slash == 0 ? "/" : file.substr(0, slash);
}

// The fixture manager the suite holds: forwards to the one the plug-in made, and keeps the
// plug-in loaded as long as it lives.
class LoadedFixtureManager : public FixtureManager {
public:
    explicit LoadedFixtureManager(std::unique_ptr<languages::LoadedFixture> loaded)
        : loaded_(std::move(loaded)) {}

    bool setup(int argc, char** argv) override {
        FixtureManager* inner = sync();
        inner->setParam(getParam());
        return inner->setup(argc, argv);
    }
    bool check() override { return sync()->check(); }
    void tearDown() override { sync()->tearDown(); }

private:
    // The suite sets its dispatcher and result on this object; the plug-in reports through its
    // own, so pass them on before each call.
    FixtureManager* sync() {
        FixtureManager* inner = loaded_->get();
        inner->setDispatcher(getDispatcher());
        inner->setResult(getResult(), getOwner());
        if (inner->getName().empty()) {
            inner->setName(getName());
        }
        return inner;
    }

    std::unique_ptr<languages::LoadedFixture> loaded_;
};

}  // namespace

// Passes the test case's events on to the run's result as events of the stand-in, and keeps
// the worst state they carried.
class InProcessExecutor::Relay : public TestListener {
public:
    void begin(TestResult& target, const Test& self) {
        target_ = &target;
        self_ = &self;
        status_ = TestStatus::Passed;
    }
    TestStatus status() const { return status_; }

    void addReport(const Test*, TestMessage msg) override { target_->addReport(self_, msg); }
    void addError(const Test*, TestMessage msg) override {
        worsen(TestStatus::Error);
        target_->addError(self_, msg);
    }
    void addFailure(const Test*, TestMessage msg) override {
        worsen(TestStatus::Failed);
        target_->addFailure(self_, msg);
    }
    void startTest(const Test*) override { target_->startTest(self_); }
    void endTest(const Test*) override { target_->endTest(self_); }
    void addCheck(const Test*, TestMessage msg, bool passed) override {
        target_->addCheck(self_, msg, passed);
    }
    void addSkipped(const Test*, TestMessage reason) override {
        worsen(TestStatus::Skipped);
        target_->addSkipped(self_, reason);
    }
    void addCrash(const Test*, TestMessage msg) override {
        worsen(TestStatus::Crashed);
        target_->addCrash(self_, msg);
    }
    void addTimeout(const Test*, TestMessage msg) override {
        worsen(TestStatus::TimedOut);
        target_->addTimeout(self_, msg);
    }
    void addInterrupted(const Test*, TestMessage msg) override {
        worsen(TestStatus::Interrupted);
        target_->addInterrupted(self_, msg);
    }
    void addOutput(const Test*, const std::string& text) override {
        target_->addOutput(self_, text);
    }

private:
    void worsen(TestStatus status) { status_ = std::max(status_, status); }

    TestResult* target_ = nullptr;
    const Test* self_ = nullptr;
    TestStatus status_ = TestStatus::Passed;
};

InProcessExecutor::InProcessExecutor() : relay_(std::make_unique<Relay>()) {
    relayed_.addListener(relay_.get());
}

InProcessExecutor::~InProcessExecutor() = default;

bool InProcessExecutor::locate(const std::string& plugin, const std::string& given,
                               const std::string& givenType, const SourceLocation& where,
                               std::string& path, std::string& type, std::string& error) {
    path = given;
    if (path.empty()) {
        std::string searched;
        path = plugin::findPlugin(plugin, folderOf(where.file), &searched);
        if (path.empty()) {
            error = "'" + plugin + "' " + searched;
            return false;
        }
    }
    type = givenType.empty() ? languages::typeFromFile(path) : givenType;
    if (type.empty()) {
        error = "cannot tell what kind of plug-in '" + path +
                "' is (not a .so, .py, .lua or .rb file, nor an executable); give its type, "
                "e.g. type=\"dll\"";
        return false;
    }
    if (!languages::isSupportedType(type)) {
        error = "'" + path + "' is a " + type + " plug-in; this build does not support " + type;
        return false;
    }
    return true;
}

TestStatus InProcessExecutor::notLoaded(const TestSpec& spec, Test& self, TestResult& result,
                                        const std::string& reason) {
    self.setName(PluginTest::displayName(spec));
    result.startTest(&self);
    result.addFailure(&self, TestMessage("cannot load " + spec.plugin, reason));
    result.endTest(&self);
    return TestStatus::Failed;
}

TestStatus InProcessExecutor::run(const TestSpec& spec, Test& self, TestResult& result) {
    std::string path;
    std::string type;
    std::string error;
    if (!locate(spec.plugin, spec.path, spec.type, spec.where, path, type, error)) {
        return notLoaded(spec, self, result, error);
    }
    std::unique_ptr<languages::LoadedTest> loaded;
    try {
        loaded = languages::loadTest(type, path, error);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (!loaded || loaded->get() == nullptr) {
        return notLoaded(spec, self, result, error);
    }

    TestCase* test = loaded->get();
    test->setParam(spec.param);
    test->setEnvironment(spec.environment);
    test->setRepetition(spec.repetition == 0 ? 1 : spec.repetition);
    if (!spec.name.empty()) {
        test->setName(spec.name);
    }
    self.setName(test->getName().empty() ? PluginTest::displayName(spec) : test->getName());
    self.setDescription(test->getDescription());

    // The test case sends its events about itself; the relay makes them the stand-in's.
    relay_->begin(result, self);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        running_ = test;
    }
    test->run(relayed_);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        running_ = nullptr;
    }
    if (test->hasCriticalError()) {
        self.setCriticalError(test->getCriticalError());
    }
    TestStatus status = relay_->status();
    if (status == TestStatus::Passed && !test->succeeded()) {
        status = TestStatus::Failed;
    }

    // Replacing the previous object of this file only now keeps its library loaded meanwhile.
    loaded_[path] = std::move(loaded);
    return status;
}

void InProcessExecutor::interrupt() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (running_ != nullptr) {
        running_->interrupt();
    }
}

std::unique_ptr<FixtureManager> InProcessExecutor::makeFixture(const FixtureSpec& spec,
                                                               std::string& error) {
    std::string path;
    std::string type;
    if (!locate(spec.plugin, spec.path, spec.type, spec.where, path, type, error)) {
        return nullptr;
    }
    std::unique_ptr<languages::LoadedFixture> loaded;
    try {
        loaded = languages::loadFixture(type, path, error);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (!loaded || loaded->get() == nullptr) {
        return nullptr;
    }
    auto manager = std::make_unique<LoadedFixtureManager>(std::move(loaded));
    manager->setName(spec.plugin);
    manager->setParam(spec.param);
    return manager;
}

}  // namespace runner
}  // namespace robottestingframework
