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
};

}  // namespace robottestingframework
