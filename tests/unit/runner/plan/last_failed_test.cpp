// --lf and --ff: a run cut down to, or reordered by, the last run's failures.
#include <gtest/gtest.h>

#include "runner/model/test_id.h"
#include "runner/plan/last_failed.h"

using namespace robottestingframework::runner;

namespace {

SuiteSpec suite(const std::string& name, const std::vector<std::string>& tests,
                const std::string& dependent = "") {
    SuiteSpec spec;
    spec.name = name;
    for (const auto& test : tests) {
        TestSpec t;
        t.name = test;
        t.plugin = test + ".so";
        if (test == dependent) {
            t.depends.push_back(tests.front());
        }
        spec.tests.push_back(t);
    }
    assignTestIds(spec, ".");
    return spec;
}

std::vector<std::string> ids(const std::vector<SuiteSpec>& suites) {
    std::vector<std::string> out;
    for (const auto& s : suites) {
        for (const auto& t : s.tests) {
            out.push_back(testId(s, t));
        }
    }
    return out;
}

}  // namespace

TEST(LastFailed, KeepsOnlyTheFailedTestsAndTheirSuites) {
    std::vector<SuiteSpec> suites{suite("a", {"x", "y"}), suite("b", {"z"}), suite("c", {"w"})};
    const std::set<std::string> failed{"a/y", "c/w", "gone/t"};
    EXPECT_EQ(countTestsNamed(suites, failed), 2u);
    keepTestsNamed(suites, failed);
    EXPECT_EQ(ids(suites), (std::vector<std::string>{"a/y", "c/w"}));
}

TEST(LastFailed, FailedFirstPutsTheirSuitesAndThemFirstKeepingTheRest) {
    std::vector<SuiteSpec> suites{suite("a", {"x", "y"}), suite("b", {"p", "q", "r"}),
                                  suite("c", {"w"})};
    putTestsNamedFirst(suites, {"b/r", "b/q", "c/w"});
    EXPECT_EQ(ids(suites), (std::vector<std::string>{"b/q", "b/r", "b/p", "c/w", "a/x", "a/y"}));
}

TEST(LastFailed, FailedFirstKeepsTheOrderOfASuiteWhoseTestsDependOnEachOther) {
    std::vector<SuiteSpec> suites{suite("a", {"x"}), suite("b", {"p", "q"}, "q")};
    putTestsNamedFirst(suites, {"b/q"});
    EXPECT_EQ(ids(suites), (std::vector<std::string>{"b/p", "b/q", "a/x"}));
}
