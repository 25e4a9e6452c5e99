// A fixture's call (setup, tearDown, check) that must not let an exception through: what it
// threw becomes the reason the suite reports. Used by TestSuite and by the runner's shared
// worlds, which run a suite's fixture in a keeper of their own.
#pragma once

#include <exception>
#include <string>

namespace robottestingframework {

// Runs `call`; returns false and fills `why` when it threw.
template <typename Call>
bool guardedCall(Call call, std::string& why) {
    try {
        call();
        return true;
    } catch (const std::exception& e) {
        why = e.what();
    } catch (...) {
        why = "unhandled exception of unknown type";
    }
    return false;
}

}  // namespace robottestingframework
