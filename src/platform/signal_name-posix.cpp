#include "platform/signal_name.h"

#include <signal.h>
#include <string.h>

namespace robottestingframework {
namespace platform {

std::string signalName(int signal) {
    switch (signal) {
        // clang-format off
        case SIGHUP: return "SIGHUP";     case SIGINT: return "SIGINT";
        case SIGQUIT: return "SIGQUIT";   case SIGILL: return "SIGILL";
        case SIGTRAP: return "SIGTRAP";   case SIGABRT: return "SIGABRT";
        case SIGBUS: return "SIGBUS";     case SIGFPE: return "SIGFPE";
        case SIGKILL: return "SIGKILL";   case SIGUSR1: return "SIGUSR1";
        case SIGSEGV: return "SIGSEGV";   case SIGUSR2: return "SIGUSR2";
        case SIGPIPE: return "SIGPIPE";   case SIGALRM: return "SIGALRM";
        case SIGTERM: return "SIGTERM";   case SIGCHLD: return "SIGCHLD";
        case SIGCONT: return "SIGCONT";   case SIGSTOP: return "SIGSTOP";
        case SIGTSTP: return "SIGTSTP";   case SIGTTIN: return "SIGTTIN";
        case SIGTTOU: return "SIGTTOU";   case SIGURG: return "SIGURG";
        case SIGXCPU: return "SIGXCPU";   case SIGXFSZ: return "SIGXFSZ";
        case SIGVTALRM: return "SIGVTALRM"; case SIGPROF: return "SIGPROF";
        case SIGWINCH: return "SIGWINCH"; case SIGIO: return "SIGIO";
        case SIGSYS: return "SIGSYS";
#ifdef SIGSTKFLT
        case SIGSTKFLT: return "SIGSTKFLT";
#endif
#ifdef SIGPWR
        case SIGPWR: return "SIGPWR";
#endif
        // clang-format on
        default:
            break;
    }
#ifdef SIGRTMIN
    if (signal >= SIGRTMIN && signal <= SIGRTMAX) {
        return signal == SIGRTMIN ? "SIGRTMIN" : "SIGRTMIN+" + std::to_string(signal - SIGRTMIN);
    }
#endif
    return "signal " + std::to_string(signal);
}

int signalNumber(const std::string& name) {
    for (int number = 1; number < NSIG; ++number) {
        if (signalName(number) == name) {
            return number;
        }
    }
    return 0;
}

int stopSignalNumber(const std::string& name) {
    return signalNumber(name);
}

std::string signalDescription(int signal) {
    const char* text = ::strsignal(signal);
    return text != nullptr ? text : signalName(signal);
}

std::string programKilledBy(int signal) {
    return "killed by " + signalName(signal);
}

}  // namespace platform
}  // namespace robottestingframework
