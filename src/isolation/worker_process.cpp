// What a worker sends, read the same way on every platform: its events from the channel,
// decoded as they come, and what it prints. Starting, waiting for and stopping it are the
// platform's (worker_process-posix.cpp: through the fork server; -windows.cpp: a job object).
#include "isolation/worker_process.h"

#include "platform/clock.h"

namespace robottestingframework {
namespace isolation {

namespace {

// Hands what `fd` has to `sink`, `readSize` bytes at most at a time: one read unless it filled
// the buffer, or (`all`) until nothing is left. At the end of the file (nothing more will come)
// `fd` is closed.
template <typename Sink>
void readPipe(platform::FileDescriptor& fd, bool all, long readSize, Sink sink) {
    std::string bytes;
    for (;;) {
        bytes.clear();
        const long n = platform::readSome(fd.get(), bytes, static_cast<std::size_t>(readSize));
        if (n > 0) {
            sink(bytes);
            if (n < readSize && !all) {
                break;
            }
            continue;
        }
        if (n == 0) {
            fd.reset();
        }
        break;
    }
}

}  // namespace

void WorkerProcess::readChannel(std::vector<WireRecord>& records, bool all) {
    readPipe(channel_, all, kReadSize, [this](const std::string& bytes) { events_.feed(bytes); });
    WireRecord record;
    for (;;) {
        WireDecoder::Status status = events_.next(record);
        if (status == WireDecoder::Status::Record) {
            records.push_back(std::move(record));
            record = WireRecord();
        } else {
            corrupt_ = corrupt_ || status == WireDecoder::Status::Corrupt;
            break;
        }
    }
    if (corrupt_) {
        channel_.reset();
    }
}

void WorkerProcess::readOutput(bool all) {
    readPipe(output_fd_, all, kReadSize,
             [this](const std::string& bytes) { output_.append(bytes); });
}

bool WorkerProcess::pump(int timeoutMs, std::vector<WireRecord>& records, int wake, bool* woken) {
    if (woken != nullptr) {
        *woken = false;
    }
    if (!backlog_.empty()) {
        records.insert(records.end(), backlog_.begin(), backlog_.end());
        backlog_.clear();
        return true;
    }
    return collect(timeoutMs, records, wake, woken);
}

bool WorkerProcess::pumpUntilEnd(double seconds, std::vector<WireRecord>& records) {
    platform::Deadline deadline(seconds);
    while (!exited_ && !deadline.expired()) {
        pump(deadline.remainingMs(100), records);
    }
    return exited_;
}

void WorkerProcess::drainOutput() {
    if (output_fd_.valid()) {
        readOutput(true);
    }
}

}  // namespace isolation
}  // namespace robottestingframework
