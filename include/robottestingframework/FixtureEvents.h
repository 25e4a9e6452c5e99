// What a fixture manager tells the suite it serves.
#pragma once

#include <string>

#include <robottestingframework/Attachment.h>
#include <robottestingframework/TestMessage.h>

namespace robottestingframework {

class FixtureEvents {
public:
    virtual ~FixtureEvents() = default;
    // The world the tests need is gone. May be called from any thread, at any time.
    virtual void fixtureCollapsed(TestMessage reason) = 0;
    // A check the fixture makes of its own, at its tear-down, failed (a process of its world
    // did not stop cleanly): the suite reports it as a record of its own named `name` (a
    // failed test of every report), with `attachment` when not null, and fails. Called from
    // tearDown(); true when the record is taken, false (this default) when the fixture must
    // say it otherwise (its tearDown throws).
    virtual bool fixtureCheckFailed(const std::string& name, const TestMessage& failure,
                                    const Attachment* attachment) {
        (void)name;
        (void)failure;
        (void)attachment;
        return false;
    }
};

}  // namespace robottestingframework
