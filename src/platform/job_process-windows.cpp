// Windows: CreateProcess with the handles the child gets named one by one, in a job object
// that kills on close. Each handle is passed as an inheritable duplicate made for this start
// alone (and closed after it), and the starts are serialized: a handle list
// (PROC_THREAD_ATTRIBUTE_HANDLE_LIST) keeps another start from inheriting them on Windows,
// the lock does where the handle list is not honoured (older Wine).
#include "platform/job_process.h"

#include <fcntl.h>
#include <io.h>
#include <windows.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>

#include "platform/system_error.h"

namespace robottestingframework {
namespace platform {

namespace {

std::mutex startMutex;

// The inheritable duplicates made for one start, closed when it is over.
class InheritedHandles {
public:
    ~InheritedHandles() {
        for (HANDLE handle : handles_) {
            ::CloseHandle(handle);
        }
    }
    HANDLE add(HANDLE original) {
        HANDLE copy = nullptr;
        if (original == INVALID_HANDLE_VALUE ||
            !::DuplicateHandle(::GetCurrentProcess(), original, ::GetCurrentProcess(), &copy, 0,
                               TRUE, DUPLICATE_SAME_ACCESS)) {
            return nullptr;
        }
        handles_.push_back(copy);
        return copy;
    }
    HANDLE addFd(int fd) { return add(reinterpret_cast<HANDLE>(::_get_osfhandle(fd))); }
    HANDLE addNull(DWORD access) {
        SECURITY_ATTRIBUTES inherit{sizeof(inherit), nullptr, TRUE};
        HANDLE null = ::CreateFileA("NUL", access, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit,
                                    OPEN_EXISTING, 0, nullptr);
        if (null == INVALID_HANDLE_VALUE) {
            return nullptr;
        }
        handles_.push_back(null);
        return null;
    }
    std::vector<HANDLE>& all() { return handles_; }

private:
    std::vector<HANDLE> handles_;
};

// Ours with `changes` applied (names compared without case, as Windows does), as the block
// CreateProcess takes: NAME=VALUE\0 ... \0.
std::string environmentBlock(const std::vector<std::pair<std::string, std::string>>& changes) {
    struct NoCase {
        bool operator()(const std::string& a, const std::string& b) const {
            return ::_stricmp(a.c_str(), b.c_str()) < 0;
        }
    };
    std::map<std::string, std::string, NoCase> variables;
    char* strings = ::GetEnvironmentStringsA();
    for (const char* entry = strings; entry != nullptr && *entry != '\0';
         entry += std::strlen(entry) + 1) {
        const std::string text(entry);
        // "=C:=C:\dir" entries (a drive's current folder) start with '='.
        const std::size_t equals = text.find('=', 1);
        if (equals != std::string::npos) {
            variables[text.substr(0, equals)] = text.substr(equals + 1);
        }
    }
    ::FreeEnvironmentStringsA(strings);
    for (const auto& change : changes) {
        variables[change.first] = change.second;
    }
    std::string block;
    for (const auto& variable : variables) {
        block += variable.first + "=" + variable.second;
        block.push_back('\0');
    }
    block.push_back('\0');
    return block;
}

std::string lowered(std::string text) {
    for (char& c : text) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return text;
}

// Whether `program` is cmd.exe (a path or a name, with or without .exe).
bool isCmd(const std::string& program) {
    const std::size_t slash = program.find_last_of("/\\");
    const std::string name =
        lowered(slash == std::string::npos ? program : program.substr(slash + 1));
    return name == "cmd.exe" || name == "cmd";
}

bool sameSwitch(const std::string& argument, const char* name) {
    return lowered(argument) == name;
}

// The command line of `argv`: each argument quoted for the C run-time, except what follows
// cmd.exe's "/s /c": cmd runs the rest of its command line as it is, once it has removed one
// pair of quotes around it, so quoting for the C run-time would reach the command as \".
std::string commandLineOf(const std::vector<std::string>& argv) {
    std::string line;
    std::size_t i = 0;
    for (; i < argv.size(); ++i) {
        line += (line.empty() ? "" : " ") + quoteArgument(argv[i]);
        if (i >= 2 && isCmd(argv[0]) && sameSwitch(argv[i - 1], "/s") &&
            sameSwitch(argv[i], "/c")) {
            ++i;
            break;
        }
    }
    if (i == argv.size()) {
        return line;
    }
    std::string rest;
    for (; i < argv.size(); ++i) {
        rest += (rest.empty() ? "" : " ") + argv[i];
    }
    return line + " \"" + rest + "\"";
}

}  // namespace

std::string quoteArgument(const std::string& argument) {
    if (!argument.empty() && argument.find_first_of(" \t\n\v\"") == std::string::npos) {
        return argument;
    }
    // Backslashes are literal unless they precede a quote: then each is doubled.
    std::string quoted = "\"";
    std::size_t backslashes = 0;
    for (char c : argument) {
        if (c == '\\') {
            ++backslashes;
            continue;
        }
        quoted.append(c == '"' ? backslashes * 2 + 1 : backslashes, '\\');
        backslashes = 0;
        quoted.push_back(c);
    }
    quoted.append(backslashes * 2, '\\');
    quoted.push_back('"');
    return quoted;
}

std::string handleValue(int fd) {
    return std::to_string(static_cast<unsigned long long>(::_get_osfhandle(fd)));
}

int descriptorOfHandle(const std::string& value) {
    char* end = nullptr;
    const unsigned long long number = std::strtoull(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || number == 0) {
        return -1;
    }
    return ::_open_osfhandle(static_cast<intptr_t>(number), _O_BINARY);
}

JobProcess::~JobProcess() {
    if (job_ != nullptr) {
        ::CloseHandle(job_);  // kill on close: whatever is left of the tree ends
    }
    if (process_ != nullptr) {
        ::CloseHandle(process_);
    }
}

bool JobProcess::start(const JobProcessOptions& options, std::string& error) {
    const std::string program = options.argv.empty() ? std::string() : options.argv[0];
    std::string commandLine = commandLineOf(options.argv);
    job_ = ::CreateJobObjectA(nullptr, nullptr);
    if (job_ == nullptr) {
        error = "cannot create a job object: " + systemErrorText(::GetLastError());
        return false;
    }
    JOBOBJECT_EXTENDED_LIMIT_INFORMATION limits{};
    // A crash ends the process with its exception code instead of waiting on a dialog.
    limits.BasicLimitInformation.LimitFlags =
        JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE | JOB_OBJECT_LIMIT_DIE_ON_UNHANDLED_EXCEPTION;
    ::SetInformationJobObject(job_, JobObjectExtendedLimitInformation, &limits, sizeof(limits));

    std::string environment;
    if (!options.environment.empty()) {
        environment = environmentBlock(options.environment);
    }
    std::lock_guard<std::mutex> lock(startMutex);
    InheritedHandles inherited;
    STARTUPINFOEXA startup{};
    startup.StartupInfo.cb = sizeof(startup);
    startup.StartupInfo.dwFlags = STARTF_USESTDHANDLES;
    startup.StartupInfo.hStdInput =
        options.stdinFd >= 0 ? inherited.addFd(options.stdinFd) : inherited.addNull(GENERIC_READ);
    startup.StartupInfo.hStdOutput = options.stdoutFd >= 0 ? inherited.addFd(options.stdoutFd)
                                                           : inherited.addNull(GENERIC_WRITE);
    startup.StartupInfo.hStdError = options.stderrFd >= 0 ? inherited.addFd(options.stderrFd)
                                                          : inherited.addNull(GENERIC_WRITE);
    for (int fd : options.inheritedFds) {
        // The child is told our handle's value: the inherited copy must carry the same one.
        HANDLE handle = reinterpret_cast<HANDLE>(::_get_osfhandle(fd));
        if (handle == INVALID_HANDLE_VALUE ||
            !::SetHandleInformation(handle, HANDLE_FLAG_INHERIT, HANDLE_FLAG_INHERIT)) {
            error = "cannot pass a pipe to " + program;
            return false;
        }
    }
    std::vector<HANDLE> list = inherited.all();
    for (int fd : options.inheritedFds) {
        list.push_back(reinterpret_cast<HANDLE>(::_get_osfhandle(fd)));
    }
    SIZE_T size = 0;
    ::InitializeProcThreadAttributeList(nullptr, 1, 0, &size);
    std::vector<char> attributes(size);
    auto* attributeList = reinterpret_cast<LPPROC_THREAD_ATTRIBUTE_LIST>(attributes.data());
    bool haveList =
        ::InitializeProcThreadAttributeList(attributeList, 1, 0, &size) &&
        ::UpdateProcThreadAttribute(attributeList, 0, PROC_THREAD_ATTRIBUTE_HANDLE_LIST,
                                    list.data(), list.size() * sizeof(HANDLE), nullptr, nullptr);
    startup.lpAttributeList = haveList ? attributeList : nullptr;

    PROCESS_INFORMATION info{};
    // A group of its own: Ctrl-C on the console is the runner's to handle, not the tests'.
    const DWORD flags =
        CREATE_SUSPENDED | CREATE_NEW_PROCESS_GROUP | (haveList ? EXTENDED_STARTUPINFO_PRESENT : 0);
    const BOOL started = ::CreateProcessA(
        nullptr, &commandLine[0], nullptr, nullptr, TRUE, flags,
        environment.empty() ? nullptr : &environment[0],
        options.workingDirectory.empty() ? nullptr : options.workingDirectory.c_str(),
        &startup.StartupInfo, &info);
    const DWORD startError = ::GetLastError();
    if (haveList) {
        ::DeleteProcThreadAttributeList(attributeList);
    }
    for (int fd : options.inheritedFds) {
        ::SetHandleInformation(reinterpret_cast<HANDLE>(::_get_osfhandle(fd)), HANDLE_FLAG_INHERIT,
                               0);
    }
    if (!started) {
        error = "cannot run " + program + ": " + systemErrorText(startError);
        return false;
    }
    if (!::AssignProcessToJobObject(job_, info.hProcess)) {
        error = "cannot put " + program + " in a job object: " + systemErrorText(::GetLastError());
        ::TerminateProcess(info.hProcess, 1);
        ::CloseHandle(info.hThread);
        ::CloseHandle(info.hProcess);
        return false;
    }
    ::ResumeThread(info.hThread);
    ::CloseHandle(info.hThread);
    process_ = info.hProcess;
    pid_ = info.dwProcessId;
    return true;
}

bool JobProcess::ended(int timeoutMs) {
    if (ended_ || process_ == nullptr) {
        return true;
    }
    if (::WaitForSingleObject(process_, timeoutMs < 0 ? INFINITE : static_cast<DWORD>(timeoutMs)) !=
        WAIT_OBJECT_0) {
        return false;
    }
    DWORD code = 0;
    ::GetExitCodeProcess(process_, &code);
    exitCode_ = code;
    ended_ = true;
    return true;
}

void JobProcess::kill(unsigned int code) {
    if (job_ != nullptr) {
        ::TerminateJobObject(job_, code);
    }
}

}  // namespace platform
}  // namespace robottestingframework
