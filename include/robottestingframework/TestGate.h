// Beyond RTF 2.x: decides, just before a test would run, that it must not (a dependency that did
// not pass, fail-fast after a failure). Such a test is reported skipped with the reason.
#pragma once

#include <robottestingframework/TestMessage.h>

namespace robottestingframework {

class Test;

class TestGate {
public:
    virtual ~TestGate() = default;
    // Returns true and fills `reason` when `test` must be skipped.
    virtual bool skip(const Test* test, TestMessage& reason) = 0;
};

}  // namespace robottestingframework
