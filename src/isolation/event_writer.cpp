#include "isolation/event_writer.h"

#include <robottestingframework/Test.h>

#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace isolation {

namespace {

std::string nameOf(const Test* test) {
    return test != nullptr ? test->getName() : std::string();
}

}  // namespace

bool EventWriter::send(const WireRecord& record) {
    std::string bytes = encode(record);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!held_.empty()) {
        bytes.insert(0, held_);
        held_.clear();
    }
    return platform::writeAll(fd_, bytes);
}

void EventWriter::hold(const WireRecord& record) {
    std::lock_guard<std::mutex> lock(mutex_);
    encode(record, held_);
}

void EventWriter::sendEvent(const ResultEvent& event, const Test* test) {
    onEvent(RunEvent{event, test});
}

void EventWriter::onEvent(const RunEvent& event) {
    const WireRecord record = eventRecord(event.data, nameOf(event.test));
    // Transport only: the runner holds a test's end back until the worker finished anyway, so
    // its record waits to share a write with the next one (the Finished record).
    if (endsTest(event.data.kind)) {
        hold(record);
    } else {
        send(record);
    }
}

}  // namespace isolation
}  // namespace robottestingframework
