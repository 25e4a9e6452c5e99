// A file a test attached to its result (a plot, a log, a camera frame): copied into the run's
// attachments folder when attached, so it outlives the test's temporary files. Recorded as an
// event of its test (ResultEvent::Kind::Attachment).
#pragma once

#include <cstdint>
#include <string>

namespace robottestingframework {

struct Attachment {
    // The copy, relative to the folder of the report outputs ("rtf-attachments/3-plot.png"):
    // what the HTML and CTRF reports link.
    std::string path;
    std::string absolutePath;  // the copy's absolute path (JUnit's [[ATTACHMENT|...]] lines)
    std::string description;
    std::string originalName;  // the file's name as the test gave it
    std::uint64_t size = 0;    // bytes

    // "image/png", "text/plain", ... from the name's extension; "application/octet-stream"
    // when unknown.
    std::string contentType() const;
};

// "rtf-attachments/3-plot.png (the tracking plot)": the attachment event's message.
std::string describeAttachment(const Attachment& attachment);

}  // namespace robottestingframework
