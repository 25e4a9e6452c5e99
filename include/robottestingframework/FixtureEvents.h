// What a fixture manager tells the suite it serves.
#pragma once

#include <robottestingframework/TestMessage.h>

namespace robottestingframework {

class FixtureEvents {
public:
    virtual ~FixtureEvents() = default;
    // The world the tests need is gone. May be called from any thread, at any time.
    virtual void fixtureCollapsed(TestMessage reason) = 0;
};

}  // namespace robottestingframework
