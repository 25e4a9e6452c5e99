// Windows: descriptors 1 and 2 of the C run-time pointed at a temporary file that Windows
// deletes when the last handle on it closes (there is no unlinking an open file).
#include "runner/execution/output_capture.h"

#include <fcntl.h>
#include <io.h>
#include <windows.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace robottestingframework {
namespace runner {

namespace {

// More than this per test is cut to its tail: the last lines are the ones that explain. The
// same 64 KiB as a worker's output (README: Isolation).
const long long maxOutput = 64 * 1024;

void flushStreams() {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(stdout);
    std::fflush(stderr);
}

void writeAll(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        int n = ::_write(fd, text.data() + done, static_cast<unsigned int>(text.size() - done));
        if (n <= 0) {
            return;
        }
        done += static_cast<std::size_t>(n);
    }
}

// A temporary file that goes away with its last handle; -1 with `error` set on failure.
int openTemporaryFile(std::string& error) {
    char folder[MAX_PATH + 1] = {};
    if (::GetTempPathA(sizeof(folder), folder) == 0) {
        error = "cannot tell the temporary folder";
        return -1;
    }
    char name[MAX_PATH + 1] = {};
    if (::GetTempFileNameA(folder, "rtf", 0, name) == 0) {
        error = std::string("cannot create a file to capture the tests' output in ") + folder;
        return -1;
    }
    HANDLE file = ::CreateFileA(
        name, GENERIC_READ | GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
        nullptr, CREATE_ALWAYS, FILE_ATTRIBUTE_TEMPORARY | FILE_FLAG_DELETE_ON_CLOSE, nullptr);
    if (file == INVALID_HANDLE_VALUE) {
        error = std::string("cannot open ") + name + " to capture the tests' output";
        ::DeleteFileA(name);
        return -1;
    }
    // Append mode: after take() empties the file, writes start again at its beginning.
    int fd = ::_open_osfhandle(reinterpret_cast<intptr_t>(file), _O_APPEND | _O_BINARY);
    if (fd < 0) {
        ::CloseHandle(file);
        error = "cannot open a descriptor on the capture file";
    }
    return fd;
}

}  // namespace

OutputCapture::~OutputCapture() {
    stop();
}

bool OutputCapture::start(std::string& error) {
    if (active()) {
        return true;
    }
    int file = openTemporaryFile(error);
    if (file < 0) {
        return false;
    }
    flushStreams();
    int savedOut = ::_dup(1);
    int savedErr = ::_dup(2);
    int consoleFd = savedOut >= 0 ? ::_dup(savedOut) : -1;
    std::FILE* console = consoleFd >= 0 ? ::_fdopen(consoleFd, "w") : nullptr;
    if (savedOut < 0 || savedErr < 0 || console == nullptr || ::_dup2(file, 1) < 0 ||
        ::_dup2(file, 2) < 0) {
        error = std::string("cannot redirect the output to capture it: ") + std::strerror(errno);
        if (savedOut >= 0) {
            ::_dup2(savedOut, 1);
            ::_close(savedOut);
        }
        if (savedErr >= 0) {
            ::_dup2(savedErr, 2);
            ::_close(savedErr);
        }
        if (console != nullptr) {
            std::fclose(console);
        } else if (consoleFd >= 0) {
            ::_close(consoleFd);
        }
        ::_close(file);
        return false;
    }
    // Line by line: if a test takes the runner down, the console still shows how far it got.
    std::setvbuf(console, nullptr, _IOLBF, 1024);
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
    ::_dup2(savedOut_, 1);
    ::_dup2(savedErr_, 2);
    ::_close(savedOut_);
    ::_close(savedErr_);
    ::_close(file_);
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
    const long long size = ::_lseeki64(file_, 0, SEEK_END);
    if (size <= 0) {
        return {};
    }
    const long long from = size > maxOutput ? size - maxOutput : 0;
    std::string text;
    if (from > 0) {
        text = "[" + std::to_string(from) + " bytes of output left out]\n";
    }
    std::size_t start = text.size();
    text.resize(start + static_cast<std::size_t>(size - from));
    ::_lseeki64(file_, from, SEEK_SET);
    std::size_t done = 0;
    while (start + done < text.size()) {
        int n = ::_read(file_, &text[start + done],
                        static_cast<unsigned int>(text.size() - start - done));
        if (n <= 0) {
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    text.resize(start + done);
    if (::_chsize_s(file_, 0) != 0) {
        // Keeping it is harmless but the same text would come again: drop it from view.
        text += "\n[the capture file could not be emptied]\n";
    }
    return text;
}

}  // namespace runner
}  // namespace robottestingframework
