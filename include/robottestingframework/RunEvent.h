// One event of a run on its way from what sends it to every listener: the event as data, and
// the objects it is about. TestResult::publish hands it to every listener's onEvent; relays
// (queues, worker streams) carry it as it is, whatever its kind.
#pragma once

#include <robottestingframework/ResultEvent.h>

namespace robottestingframework {

class Test;
class TestSuite;

struct RunEvent {
    ResultEvent data;
    const Test* test = nullptr;        // the test it is about (a suite's events: the suite)
    const TestSuite* suite = nullptr;  // for StartSuite and EndSuite: the suite
    // When it happened (steady clock, seconds since its epoch), if a relay kept it a while:
    // under -j N a suite's events wait while the scheduler's thread runs another suite, and a
    // collector times them when they happened, not when they arrived. 0: now.
    double happened = 0;
};

}  // namespace robottestingframework
