// What a worker sends, read the same way on every platform: its events from the channel,
// decoded as they come, and what it prints. Starting, waiting for and stopping it are the
// platform's (worker_process-posix.cpp: through the fork server; -windows.cpp: a job object).
#include "isolation/worker_process.h"

#include "platform/clock.h"

namespace robottestingframework {
namespace isolation {

void WorkerProcess::readChannel(std::vector<WireRecord>& records, bool all) {
    std::string bytes;
    for (;;) {
        bytes.clear();
        long n = platform::readSome(channel_.get(), bytes, kReadSize);
        if (n > 0) {
            events_.feed(bytes);
            if (n < kReadSize && !all) {
                break;
            }
            continue;
        }
        if (n == 0) {
            channel_.reset();  // end of file: nothing more will come
        }
        break;
    }
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
    std::string bytes;
    for (;;) {
        bytes.clear();
        long n = platform::readSome(output_fd_.get(), bytes, kReadSize);
        if (n > 0) {
            output_.append(bytes);
            if (n < kReadSize && !all) {
                break;
            }
            continue;
        }
        if (n == 0) {
            output_fd_.reset();
        }
        break;
    }
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
