// Writes a collected run as plain text.
#pragma once

#include <string>

#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestResultCollector.h>

namespace robottestingframework {

class TextOutputter {
public:
    explicit TextOutputter(TestResultCollector& collector, bool verbose = false);

    // Writes the file whole (a temporary name, then renamed). On failure returns false and,
    // when `error` is given, says why.
    bool write(std::string filename, bool summary = true, TestMessage* error = nullptr);
    // The same text, for printing.
    std::string text(bool summary = true) const;

private:
    TestResultCollector& collector_;
    bool verbose_;
};

}  // namespace robottestingframework
