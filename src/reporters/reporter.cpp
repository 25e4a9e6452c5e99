#include "reporters/reporter.h"

#include "reporters/atomic_file.h"

namespace robottestingframework {
namespace reporters {

namespace {

// The text into a file, 64 KiB at a time.
class FileText : public ReportText {
public:
    explicit FileText(AtomicFile& file) : ReportText(block), file_(file) { text_.reserve(block); }
    void finish() { handOn({}); }

protected:
    void handOn(std::string_view more) override {
        if (text_.size() + more.size() <= block) {
            text_.append(more.data(), more.size());
            more = {};
        }
        file_.write(text_.data(), text_.size());
        text_.clear();
        file_.write(more.data(), more.size());
    }

private:
    static constexpr std::size_t block = 64 * 1024;
    AtomicFile& file_;
};

}  // namespace

std::string Reporter::document() {
    WholeReportText text;
    writeDocument(text);
    return text.take();
}

bool Reporter::write(const std::string& filename, TestMessage* error) {
    std::string why;
    AtomicFile file;
    if (file.open(filename, why)) {
        FileText text(file);
        writeDocument(text);
        text.finish();
        if (file.commit(why)) {
            return true;
        }
    }
    reportWriteError(why, error);
    return false;
}

}  // namespace reporters
}  // namespace robottestingframework
