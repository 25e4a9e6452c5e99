// A test plug-in that sends one event of the kind reserved for the runner's own tests
// (ResultEvent::Kind::Probe), as data through TestResult::publish, and nothing else that
// fails. The kind has its rows in the tables and nothing more: if any relay between this test
// and a report dropped it, the test would show as passed there
// (tests/e2e/test_event_kinds.py).
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class ProbeEvent : public robottestingframework::TestCase {
public:
    ProbeEvent() : TestCase("ProbeEvent") {}
    void run() override {
        using namespace robottestingframework;
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("before the probe");
        RunEvent probe;
        probe.data.kind = ResultEvent::Kind::Probe;
        probe.data.message = TestMessage("the probe arrived", "sent as data", "probe_event.cpp", 7);
        probe.test = this;
        getResult()->publish(probe);
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "after the probe");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(ProbeEvent)
