// Prepares the world a suite's tests need, checks it before each test, and takes it down.
#pragma once

#include <string>

#include <robottestingframework/FixtureEvents.h>
// What RTF 2.x's FixtureManager.h brought along; fixtures written for it rely on them.
#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestResult.h>

namespace robottestingframework {

class Test;
class TestResult;

class FixtureManager {
public:
    explicit FixtureManager(FixtureEvents* dispatcher = nullptr, std::string param = "");
    explicit FixtureManager(std::string param);
    virtual ~FixtureManager();

    // What a suite calls: splits the param by RTF 2.x's rules (ArgumentVector) and calls
    // setup(argc, argv).
    bool setup();
    // RTF 2.x's layout: argv holds the param's words only, the first one in argv[0] (a
    // param "--robot icubSim" gives argc 2, argv[0] "--robot"); an empty param gives argc 0.
    virtual bool setup(int argc, char** argv);
    // Called before every test of the suite; false collapses the fixture.
    virtual bool check() { return true; }
    virtual void tearDown() {}

    void setDispatcher(FixtureEvents* dispatcher) { dispatcher_ = dispatcher; }
    FixtureEvents* getDispatcher() { return dispatcher_; }
    void setParam(const std::string& param) { param_ = param; }
    std::string getParam() const { return param_; }
    void setName(const std::string& name) { name_ = name; }
    std::string getName() const { return name_; }

    // Where ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT sends its messages (set by the suite).
    void setResult(TestResult* result, const Test* owner);
    TestResult* getResult() { return result_; }
    const Test* getOwner() const { return owner_; }

private:
    FixtureEvents* dispatcher_;
    std::string param_;
    std::string name_;
    TestResult* result_ = nullptr;
    const Test* owner_ = nullptr;
};

}  // namespace robottestingframework
