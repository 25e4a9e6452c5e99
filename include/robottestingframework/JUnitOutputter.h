// Writes a collected run as JUnit XML (the schema Jenkins, GitLab and GitHub read): one
// testsuite per suite, one testcase per test.
#pragma once

#include <string>

#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestResultCollector.h>

namespace robottestingframework {

class JUnitOutputter {
public:
    explicit JUnitOutputter(TestResultCollector& collector, bool verbose = false);

    // Writes the file whole (a temporary name, then renamed).
    bool write(std::string filename, TestMessage* error = nullptr);
    std::string xml() const;

private:
    TestResultCollector& collector_;
    bool verbose_;
};

}  // namespace robottestingframework
