// Linux: a network namespace. As root it is made on a short-lived thread of its own
// (unshare(CLONE_NEWNET) moves only that thread); otherwise a short-lived child makes a user
// namespace that maps this user to itself and the network namespace inside it. Either way
// loopback is brought up with an ioctl on a socket inside it (no `ip` program needed) and the
// namespace is kept by a descriptor of /proc/.../ns/net.
#include "platform/private_network.h"

#include <errno.h>
#include <fcntl.h>
#include <net/if.h>
#include <sched.h>
#include <signal.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <thread>

namespace robottestingframework {
namespace platform {

namespace {

// Loopback up, multicast on it, in the calling thread's network. 0 or the errno.
int bringLoopbackUp() {
    const int s = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (s < 0) {
        return errno;
    }
    struct ifreq request;
    ::memset(&request, 0, sizeof request);
    ::memcpy(request.ifr_name, "lo", 3);
    int code = 0;
    if (::ioctl(s, SIOCGIFFLAGS, &request) != 0) {
        code = errno;
    } else {
        request.ifr_flags |= IFF_UP | IFF_RUNNING | IFF_MULTICAST;
        if (::ioctl(s, SIOCSIFFLAGS, &request) != 0) {
            code = errno;
        }
    }
    ::close(s);
    return code;
}

std::string readSetting(const char* path) {
    std::ifstream in(path);
    std::string value;
    std::getline(in, value);
    return value;
}

// Why the kernel refused a user namespace, with the setting that allows one.
std::string userNamespaceHint() {
    if (readSetting("/proc/sys/kernel/unprivileged_userns_clone") == "0") {
        return "; user namespaces are disabled for users other than root by the sysctl "
               "kernel.unprivileged_userns_clone = 0 (set it to 1, or run as root)";
    }
    if (readSetting("/proc/sys/user/max_user_namespaces") == "0") {
        return "; user namespaces are disabled by the sysctl user.max_user_namespaces = 0 (set "
               "it above 0, or run as root)";
    }
    if (readSetting("/proc/sys/kernel/apparmor_restrict_unprivileged_userns") == "1") {
        return "; AppArmor restricts user namespaces (the sysctl "
               "kernel.apparmor_restrict_unprivileged_userns = 1: set it to 0, or give the "
               "runner an AppArmor profile that allows userns, or run as root)";
    }
    return "; user namespaces may be disabled (the sysctls kernel.unprivileged_userns_clone and "
           "user.max_user_namespaces allow them) or refused by a container's seccomp profile";
}

// A limit of namespaces reached (ENOSPC): the sysctls that set them.
std::string limitHint() {
    return "; a limit of namespaces is reached: the sysctls user.max_net_namespaces = " +
           readSetting("/proc/sys/user/max_net_namespaces") +
           " and user.max_user_namespaces = " + readSetting("/proc/sys/user/max_user_namespaces") +
           " (raise them)";
}

std::string threadNetworkPath() {
    return "/proc/self/task/" + std::to_string(::syscall(SYS_gettid)) + "/ns/net";
}

// As root: a thread moves itself into a new network namespace, brings loopback up and leaves
// a descriptor of it.
std::unique_ptr<PrivateNetwork> createDirectly(std::string& error, int& code) {
    FileDescriptor network;
    std::string step;
    code = 0;
    std::thread maker([&] {
        if (::unshare(CLONE_NEWNET) != 0) {
            code = errno;
            step = "unshare(CLONE_NEWNET)";
            return;
        }
        if ((code = bringLoopbackUp()) != 0) {
            step = "bringing loopback up";
            return;
        }
        network.reset(::open(threadNetworkPath().c_str(), O_RDONLY | O_CLOEXEC));
        if (!network.valid()) {
            code = errno;
            step = "opening its /proc/.../ns/net";
        }
    });
    maker.join();
    if (code != 0) {
        error = step + ": " + ::strerror(code) + (code == ENOSPC ? limitHint() : "");
        return nullptr;
    }
    return std::make_unique<PrivateNetwork>(FileDescriptor(), std::move(network));
}

// Not root: a child makes a user namespace (this user mapped to itself) and a network
// namespace in it, brings loopback up and waits while we open both from /proc. Between fork
// and _exit only system calls: this process has threads.
std::unique_ptr<PrivateNetwork> createInUserNamespace(std::string& error) {
    const std::string uidMap =
        std::to_string(::geteuid()) + " " + std::to_string(::geteuid()) + " 1\n";
    const std::string gidMap =
        std::to_string(::getegid()) + " " + std::to_string(::getegid()) + " 1\n";
    FileDescriptor readyRead, readyWrite, holdRead, holdWrite;
    if (!makePipe(readyRead, readyWrite) || !makePipe(holdRead, holdWrite)) {
        error = std::string("pipe: ") + ::strerror(errno);
        return nullptr;
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        error = std::string("fork: ") + ::strerror(errno);
        return nullptr;
    }
    if (pid == 0) {
        // Our copies of the parent's ends: the hold pipe's end of file must come when the
        // parent closes its end.
        ::close(holdWrite.get());
        ::close(readyRead.get());
        // [0]: which step failed (0: none), [1]: its errno.
        int answer[2] = {0, 0};
        auto writeFile = [](const char* path, const char* text, std::size_t size) {
            const int fd = ::open(path, O_WRONLY | O_CLOEXEC);
            if (fd < 0) {
                return errno;
            }
            const bool whole = ::write(fd, text, size) == static_cast<ssize_t>(size);
            const int code = whole ? 0 : errno;
            ::close(fd);
            return code;
        };
        // A process that changed its user (setuid) is not dumpable: its /proc/self/uid_map
        // would be root's to write, not its own.
        ::prctl(PR_SET_DUMPABLE, 1, 0, 0, 0);
        if (::unshare(CLONE_NEWUSER | CLONE_NEWNET) != 0) {
            answer[0] = 1;
            answer[1] = errno;
        } else if ((answer[1] = writeFile("/proc/self/setgroups", "deny", 4)) != 0 ||
                   (answer[1] = writeFile("/proc/self/uid_map", uidMap.data(), uidMap.size())) !=
                       0 ||
                   (answer[1] = writeFile("/proc/self/gid_map", gidMap.data(), gidMap.size())) !=
                       0) {
            answer[0] = 2;
        } else if ((answer[1] = bringLoopbackUp()) != 0) {
            answer[0] = 3;
        }
        ssize_t ignored = ::write(readyWrite.get(), answer, sizeof answer);
        (void)ignored;
        char byte;
        ignored = ::read(holdRead.get(), &byte, 1);  // until the parent closes its end
        ::_exit(0);
    }
    readyWrite.reset();
    holdRead.reset();
    int answer[2] = {0, 0};
    ssize_t got;
    do {
        got = ::read(readyRead.get(), answer, sizeof answer);
    } while (got < 0 && errno == EINTR);
    FileDescriptor user, network;
    if (got != static_cast<ssize_t>(sizeof answer)) {
        error = "the child making it ended first";
    } else if (answer[0] == 1) {
        error = std::string("unshare(CLONE_NEWUSER|CLONE_NEWNET): ") + ::strerror(answer[1]) +
                (answer[1] == ENOSPC ? limitHint() : userNamespaceHint());
    } else if (answer[0] == 2) {
        error = std::string("mapping this user in the user namespace: ") + ::strerror(answer[1]);
    } else if (answer[0] == 3) {
        error = std::string("bringing loopback up: ") + ::strerror(answer[1]);
    } else {
        const std::string base = "/proc/" + std::to_string(pid) + "/ns/";
        user.reset(::open((base + "user").c_str(), O_RDONLY | O_CLOEXEC));
        network.reset(::open((base + "net").c_str(), O_RDONLY | O_CLOEXEC));
        if (!user.valid() || !network.valid()) {
            error = "opening " + base + "user and net: " + ::strerror(errno);
        }
    }
    holdWrite.reset();  // the child ends; the namespaces stay with our descriptors
    int status;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!error.empty()) {
        return nullptr;
    }
    return std::make_unique<PrivateNetwork>(std::move(user), std::move(network));
}

}  // namespace

std::unique_ptr<PrivateNetwork> PrivateNetwork::create(std::string& error) {
    std::string direct;
    if (::geteuid() == 0) {
        int code = 0;
        auto made = createDirectly(direct, code);
        if (made || code != EPERM) {
            error = made ? "" : "a private network cannot be made: " + direct;
            return made;
        }
        // Root without CAP_SYS_ADMIN (a container): a user namespace may still be allowed.
    }
    std::string nested;
    auto made = createInUserNamespace(nested);
    if (!made) {
        error = "a private network cannot be made: " + nested;
        if (!direct.empty()) {
            error += " (as root, " + direct + ")";
        }
    }
    return made;
}

std::vector<int> PrivateNetwork::descriptors() const {
    if (user_.valid()) {
        return {user_.get(), network_.get()};
    }
    return {network_.get()};
}

bool joinPrivateNetwork(const std::vector<int>& descriptors, std::string& error) {
    if (descriptors.size() == 2 && ::setns(descriptors[0], CLONE_NEWUSER) != 0) {
        error = std::string("setns(user namespace): ") + ::strerror(errno);
        return false;
    }
    if (descriptors.empty() || descriptors.size() > 2 ||
        ::setns(descriptors.back(), CLONE_NEWNET) != 0) {
        error = std::string("setns(network namespace): ") +
                (descriptors.empty() || descriptors.size() > 2 ? "no namespace given"
                                                               : ::strerror(errno));
        return false;
    }
    return true;
}

ThreadInNetwork::~ThreadInNetwork() {
    if (home_.valid()) {
        ::setns(home_.get(), CLONE_NEWNET);
    }
}

bool ThreadInNetwork::enter(const PrivateNetwork& network, std::string& error) {
    if (!network.joinableByThread()) {
        error =
            "a thread cannot join a network made in a user namespace (only a process with "
            "one thread can)";
        return false;
    }
    if (!home_.valid()) {
        home_.reset(::open(threadNetworkPath().c_str(), O_RDONLY | O_CLOEXEC));
        if (!home_.valid()) {
            error = "opening this thread's /proc/.../ns/net: " + std::string(::strerror(errno));
            return false;
        }
    }
    if (::setns(network.descriptors().back(), CLONE_NEWNET) != 0) {
        error = std::string("setns(network namespace): ") + ::strerror(errno);
        return false;
    }
    return true;
}

}  // namespace platform
}  // namespace robottestingframework
