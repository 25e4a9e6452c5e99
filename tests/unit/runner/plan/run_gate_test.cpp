// Which tests the runner skips before they run (depends, --fail-fast), and the timeout each
// test gets from the command line, its suite and itself.
#include <gtest/gtest.h>

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <robottestingframework/TestResult.h>

#include "runner/model/stand_in_test.h"
#include "runner/model/test_executor.h"
#include "runner/plan/run_gate.h"
#include "runner/plan/run_plan.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

namespace {

// Reports each test with the state its param names ("passed", "failed", ...).
class ScriptedExecutor : public TestExecutor {
public:
    TestStatus run(const TestSpec& spec, Test& self, TestResult& result) override {
        result.startTest(&self);
        if (spec.param == "failed") {
            result.addFailure(&self, TestMessage("no"));
        }
        result.endTest(&self);
        return spec.param == "failed" ? TestStatus::Failed : TestStatus::Passed;
    }
    void interrupt() override {}
    std::unique_ptr<FixtureManager> makeFixture(const FixtureSpec&, std::string&) override {
        return nullptr;
    }
};

TestSpec spec(const std::string& name, const std::string& plugin, const std::string& param = "",
              std::vector<std::string> depends = {}) {
    TestSpec test;
    test.name = name;
    test.plugin = plugin;
    test.param = param;
    test.depends = std::move(depends);
    test.where = SourceLocation{"suite.xml", 7};
    return test;
}

}  // namespace

TEST(RunGate, UnknownDependencyNamesFileAndLine) {
    SuiteSpec suite;
    suite.tests = {spec("a", "lib/libarm.so"), spec("b", "x.so", "", {"nobody"})};
    EXPECT_EQ(findUnknownDependency({suite}).rfind("suite.xml:7: unknown dependency 'nobody'", 0),
              0u);
    for (const char* known : {"a", "lib/libarm.so", "libarm.so", "arm"}) {
        suite.tests[1].depends = {known};
        EXPECT_EQ(findUnknownDependency({suite}), "") << known;
    }
    suite.tests[1].depends = {"b"};  // itself: known, and a cycle
    EXPECT_EQ(findUnknownDependency({suite}), "");
}

TEST(RunGate, DependencyCyclesAreFoundWithFileAndLine) {
    SuiteSpec suite;
    suite.tests = {spec("a", "a.so", "", {"b"}), spec("b", "b.so", "", {"a"}),
                   spec("c", "c.so", "", {"a"})};
    suite.tests[1].where.line = 8;
    EXPECT_EQ(findDependencyCycle({suite}),
              "suite.xml:7: dependency cycle: a (suite.xml:7) depends on b (suite.xml:8), which "
              "depends on a (suite.xml:7)");

    suite.tests[1].depends = {"c"};  // a -> b -> c -> a
    suite.tests[2].where.line = 9;
    EXPECT_EQ(findDependencyCycle({suite}),
              "suite.xml:7: dependency cycle: a (suite.xml:7) depends on b (suite.xml:8), which "
              "depends on c (suite.xml:9), which depends on a (suite.xml:7)");

    suite.tests = {spec("a", "a.so", "", {"a"})};
    EXPECT_EQ(findDependencyCycle({suite}),
              "suite.xml:7: dependency cycle: a (suite.xml:7) depends on itself");

    suite.tests = {spec("a", "a.so"), spec("b", "b.so", "", {"a"}), spec("c", "c.so", "", {"b"})};
    EXPECT_EQ(findDependencyCycle({suite}), "");
}

TEST(RunGate, DependencyMustHaveRunAndPassed) {
    std::deque<TestSpec> specs{spec("good", "g.so"), spec("bad", "b.so", "failed"),
                               spec("late", "l.so")};
    ScriptedExecutor executor;
    std::deque<PluginTest> tests;
    for (const auto& s : specs) {
        tests.emplace_back(s, executor);
    }
    RunGate gate(tests);
    TestResult result;
    tests[0].run(result);
    tests[1].run(result);

    TestSpec onGood = spec("x", "x.so", "", {"good"});
    TestSpec onBad = spec("y", "y.so", "", {"bad"});
    TestSpec onLate = spec("z", "z.so", "", {"late"});
    PluginTest x(onGood, executor), y(onBad, executor), z(onLate, executor);
    TestMessage reason;
    EXPECT_FALSE(gate.skip(&x, reason));
    ASSERT_TRUE(gate.skip(&y, reason));
    EXPECT_NE(reason.getMessage().find("depends on bad, which did not pass (failed)"),
              std::string::npos)
        << reason.getMessage();
    ASSERT_TRUE(gate.skip(&z, reason));
    EXPECT_NE(reason.getMessage().find("did not run"), std::string::npos);
}

namespace {

// The event of `kind` about `test`, as TestResult::publish hands it to the gate.
RunEvent eventOf(ResultEvent::Kind kind, const Test* test) {
    RunEvent event;
    event.data.kind = kind;
    event.data.message = TestMessage("boom");
    event.test = test;
    return event;
}

}  // namespace

TEST(RunGate, FailFastSkipsEverythingAfterTheFirstFailure) {
    std::deque<PluginTest> none;
    RunGate gate(none);
    gate.setFailFast(true);
    ScriptedExecutor executor;
    TestSpec s = spec("t", "t.so");
    PluginTest test(s, executor);
    TestMessage reason;
    EXPECT_FALSE(gate.skip(&test, reason));
    gate.onEvent(eventOf(ResultEvent::Kind::Report, &test));  // a report trips nothing
    gate.onEvent(eventOf(ResultEvent::Kind::Skipped, &test));
    EXPECT_FALSE(gate.skip(&test, reason));
    gate.onEvent(eventOf(ResultEvent::Kind::Failure, &test));
    ASSERT_TRUE(gate.skip(&test, reason));
    EXPECT_NE(reason.getMessage().find("--fail-fast"), std::string::npos);
    gate.onEvent(eventOf(ResultEvent::Kind::Retry, &test));  // it runs again: not failed yet
    EXPECT_FALSE(gate.skip(&test, reason));
    gate.onEvent(eventOf(ResultEvent::Kind::Crash, &test));
    EXPECT_TRUE(gate.skip(&test, reason));

    RunGate patient(none);  // without --fail-fast a failure skips nothing
    patient.onEvent(eventOf(ResultEvent::Kind::Failure, &test));
    EXPECT_FALSE(patient.skip(&test, reason));
}

TEST(RunPlan, MostSpecificTimeoutWins) {
    SuiteSpec suite;
    suite.tests = {spec("own", "a.so"), spec("inherits", "b.so")};
    suite.tests[0].timeout = 0.5;
    Overrides overrides;
    overrides.timeout = 9;
    SuiteSpec withSuite = suite;
    withSuite.timeout = 2;
    applyOverrides(withSuite, overrides);
    EXPECT_EQ(withSuite.tests[0].timeout, 0.5);
    EXPECT_EQ(withSuite.tests[1].timeout, 2);
    applyOverrides(suite, overrides);
    EXPECT_EQ(suite.tests[1].timeout, 9);
}
