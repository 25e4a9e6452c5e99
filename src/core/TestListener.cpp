#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestSuite.h>

namespace robottestingframework {

void TestListener::startTestSuite(const TestSuite* suite) {
    startTestSuite(static_cast<const Test*>(suite));
}

void TestListener::startRepetition(const Test* test, unsigned int index, unsigned int count) {
    addReport(test, repetitionMessage(index, count));
}

void TestListener::endTestSuite(const TestSuite* suite) {
    endTestSuite(static_cast<const Test*>(suite));
}

}  // namespace robottestingframework
