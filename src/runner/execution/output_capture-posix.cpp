#include "runner/execution/output_capture.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace robottestingframework {
namespace runner {

namespace {

// More than this per test is cut to its tail: the last lines are the ones that explain. The
// same 64 KiB as a worker's output (README: Isolation).
const off_t maxOutput = 64 * 1024;

void flushStreams() {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(stdout);
    std::fflush(stderr);
}

void writeAll(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            return;
        }
        done += static_cast<std::size_t>(n);
    }
}

}  // namespace

OutputCapture::~OutputCapture() {
    stop();
}

bool OutputCapture::start(std::string& error) {
    if (active()) {
        return true;
    }
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") +
                          "/robottestingframework-output-XXXXXX";
    int file = ::mkstemp(&pattern[0]);
    if (file < 0) {
        error = "cannot create a file to capture the tests' output in " + pattern + ": " +
                std::strerror(errno);
        return false;
    }
    ::unlink(pattern.c_str());
    // Append mode: after take() empties the file, writes start again at its beginning.
    ::fcntl(file, F_SETFL, ::fcntl(file, F_GETFL) | O_APPEND);
    ::fcntl(file, F_SETFD, FD_CLOEXEC);

    flushStreams();
    int savedOut = ::fcntl(1, F_DUPFD_CLOEXEC, 3);
    int savedErr = ::fcntl(2, F_DUPFD_CLOEXEC, 3);
    int consoleFd = savedOut >= 0 ? ::fcntl(savedOut, F_DUPFD_CLOEXEC, 3) : -1;
    std::FILE* console = consoleFd >= 0 ? ::fdopen(consoleFd, "w") : nullptr;
    if (savedOut < 0 || savedErr < 0 || console == nullptr || ::dup2(file, 1) < 0 ||
        ::dup2(file, 2) < 0) {
        error = std::string("cannot redirect the output to capture it: ") + std::strerror(errno);
        if (savedOut >= 0) {
            ::dup2(savedOut, 1);
            ::close(savedOut);
        }
        if (savedErr >= 0) {
            ::dup2(savedErr, 2);
            ::close(savedErr);
        }
        if (console != nullptr) {
            std::fclose(console);
        } else if (consoleFd >= 0) {
            ::close(consoleFd);
        }
        ::close(file);
        return false;
    }
    // Line by line: if a test takes the runner down, the console still shows how far it got.
    std::setvbuf(console, nullptr, _IOLBF, 0);
    file_ = file;
    savedOut_ = savedOut;
    savedErr_ = savedErr;
    console_ = console;
    return true;
}

void OutputCapture::stop() {
    if (!active()) {
        return;
    }
    std::string rest = take();
    std::fflush(console_);
    ::dup2(savedOut_, 1);
    ::dup2(savedErr_, 2);
    ::close(savedOut_);
    ::close(savedErr_);
    ::close(file_);
    std::fclose(console_);
    file_ = savedOut_ = savedErr_ = -1;
    console_ = nullptr;
    writeAll(1, rest);
}

std::string OutputCapture::take() {
    if (!active()) {
        return {};
    }
    flushStreams();
    // The file only grows by appends, so its end is its size; cheaper than fstat, and this
    // runs twice per test.
    const off_t size = ::lseek(file_, 0, SEEK_END);
    if (size <= 0) {
        return {};
    }
    off_t from = size > maxOutput ? size - maxOutput : 0;
    std::string text;
    if (from > 0) {
        text = "[" + std::to_string(from) + " bytes of output left out]\n";
    }
    std::size_t start = text.size();
    text.resize(start + static_cast<std::size_t>(size - from));
    std::size_t done = 0;
    while (start + done < text.size()) {
        ssize_t n = ::pread(file_, &text[start + done], text.size() - start - done,
                            from + static_cast<off_t>(done));
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    text.resize(start + done);
    if (::ftruncate(file_, 0) != 0) {
        // Keeping it is harmless but the same text would come again: drop it from view.
        text += "\n[the capture file could not be emptied]\n";
    }
    return text;
}

}  // namespace runner
}  // namespace robottestingframework
