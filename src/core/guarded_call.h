// A fixture's call (setup, tearDown, check) that must not let an exception through: what it
// threw becomes the reason the suite reports. Used by TestSuite and by the runner's shared
// worlds, which run a suite's fixture in a keeper of their own, and by the fixture worker
// (--isolation process), which sends the reason to the runner.
#pragma once

#include <exception>
#include <string>

#include <robottestingframework/Exception.h>

namespace robottestingframework {

// What an exception says, as the suite reports it. An RTF exception's message is taken whole,
// not through what(): a C string ends at the first NUL, and a world process's last lines (or any
// text a fixture quotes) may hold one, which cut the rest of the failure away.
inline std::string exceptionReason(const std::exception& e) {
    const auto* rtf = dynamic_cast<const Exception*>(&e);
    return rtf != nullptr ? rtf->text() : std::string(e.what());
}

// Runs `call`; returns false and fills `why` when it threw.
template <typename Call>
bool guardedCall(Call call, std::string& why) {
    try {
        call();
        return true;
    } catch (const std::exception& e) {
        why = exceptionReason(e);
    } catch (...) {
        why = "unhandled exception of unknown type";
    }
    return false;
}

}  // namespace robottestingframework
