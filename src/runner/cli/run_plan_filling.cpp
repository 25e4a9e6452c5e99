#include "runner/cli/run_plan_filling.h"

#include "runner/cli/run_facts.h"

namespace robottestingframework {
namespace runner {

void fillRunPlan(const Options& options, RunPlan& plan, PlannedRun& planned,
                 const RunInputs& inputs, KeptWorld& kept, bool htmlReport) {
    plan.gate().setFailFast(options.failFast);
    plan.setRetries(options.retries);
    for (auto& suite : planned.suites) {
        applyOverrides(suite, inputs.overrides);
        if (htmlReport) {
            // Each test's param, tags and type, and its history strip: only the HTML report
            // shows them (10 000 tests' facts are a map of 10 000 entries).
            addTestFacts(suite, planned.reportSettings.testFacts);
        }
        plan.addSuite(std::move(suite));
    }
    if (kept.fixture) {
        plan.suite(0).addFixtureManager(kept.fixture.get());
    }
    planned.suites.clear();
}

}  // namespace runner
}  // namespace robottestingframework
