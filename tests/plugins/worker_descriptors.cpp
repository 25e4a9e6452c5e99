// A test plug-in that looks at the descriptors its worker gave it: stdin reads nothing (it is
// /dev/null, whatever the runner's stdin is), stdout and stderr are one pipe, the channel (3)
// is close-on-exec so that a program the test runs cannot write on it, and nothing else is
// open. Each check says what it found.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class WorkerDescriptors : public robottestingframework::TestCase {
public:
    WorkerDescriptors() : TestCase("WorkerDescriptors") {}
    void run() override {
        char byte;
        const ssize_t n = ::read(0, &byte, 1);
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(
            n == 0, "stdin is at its end (read gave " + std::to_string(n) + ")");
        struct stat out {};
        struct stat err {};
        const bool statted = ::fstat(1, &out) == 0 && ::fstat(2, &err) == 0;
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(statted && S_ISFIFO(out.st_mode) &&
                                             out.st_ino == err.st_ino && out.st_dev == err.st_dev,
                                         "stdout and stderr are one pipe");
        const int flags = ::fcntl(3, F_GETFD);
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(flags >= 0 && (flags & FD_CLOEXEC) != 0,
                                         "the channel (3) is open and close-on-exec");
        std::string open;
        for (int fd = 4; fd < 256; ++fd) {
            if (::fcntl(fd, F_GETFD) >= 0) {
                open += " " + std::to_string(fd);
            }
        }
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(open.empty(),
                                         "nothing above 3 is open (open:" + open + ")");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(WorkerDescriptors)
