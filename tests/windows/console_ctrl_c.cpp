// console_ctrl_c.exe READY_FILE PROGRAM [ARGS...]: a user's Ctrl-C, for the Windows end-to-end
// tests under Wine (a POSIX signal sent to wine64 is not a console event). Starts PROGRAM in
// this console and process group, waits (at most 60 s) for READY_FILE to exist, sends Ctrl-C
// to the console's processes, which this program ignores, and exits with PROGRAM's status.
#include <windows.h>

#include <cstdio>
#include <string>

namespace {

// One argument as CommandLineToArgvW reads it back: quoted, with its quotes and the
// backslashes before them escaped.
std::string quoted(const std::string& argument) {
    std::string out = "\"";
    std::size_t backslashes = 0;
    for (char c : argument) {
        if (c == '\\') {
            ++backslashes;
            continue;
        }
        out.append(c == '"' ? backslashes * 2 + 1 : backslashes, '\\');
        backslashes = 0;
        out += c;
    }
    out.append(backslashes * 2, '\\');
    return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: console_ctrl_c READY_FILE PROGRAM [ARGS...]\n");
        return 2;
    }
    std::string commandLine;
    for (int i = 2; i < argc; ++i) {
        commandLine += (i > 2 ? " " : "") + quoted(argv[i]);
    }
    // Ctrl-C goes to a console's processes; PROGRAM keeps this program's standard handles.
    STARTUPINFOA startup{};
    startup.cb = sizeof(startup);
    startup.dwFlags = STARTF_USESTDHANDLES;
    startup.hStdInput = GetStdHandle(STD_INPUT_HANDLE);
    startup.hStdOutput = GetStdHandle(STD_OUTPUT_HANDLE);
    startup.hStdError = GetStdHandle(STD_ERROR_HANDLE);
    // Wine gives a program started from pipes a console that takes no Ctrl-C: a new one.
    FreeConsole();
    if (!AllocConsole()) {
        std::fprintf(stderr, "console_ctrl_c: AllocConsole failed (error %lu)\n",
                     static_cast<unsigned long>(GetLastError()));
    }
    PROCESS_INFORMATION process{};
    if (!CreateProcessA(nullptr, &commandLine[0], nullptr, nullptr, TRUE, 0, nullptr, nullptr,
                        &startup, &process)) {
        std::fprintf(stderr, "console_ctrl_c: cannot start %s (error %lu)\n", argv[2],
                     static_cast<unsigned long>(GetLastError()));
        return 2;
    }
    CloseHandle(process.hThread);
    bool ready = false;
    for (int waited = 0; waited < 60000 && !ready; waited += 50) {
        if (WaitForSingleObject(process.hProcess, 50) == WAIT_OBJECT_0) {
            break;  // ended before it was ready: its status tells
        }
        ready = GetFileAttributesA(argv[1]) != INVALID_FILE_ATTRIBUTES;
    }
    // Ignored here from now on (set before CreateProcess, PROGRAM would inherit it and ignore
    // Ctrl-C whatever its handler).
    SetConsoleCtrlHandler(nullptr, TRUE);
    if (ready && !GenerateConsoleCtrlEvent(CTRL_C_EVENT, 0)) {
        std::fprintf(stderr, "console_ctrl_c: GenerateConsoleCtrlEvent failed (error %lu)\n",
                     static_cast<unsigned long>(GetLastError()));
    }
    if (WaitForSingleObject(process.hProcess, 60000) != WAIT_OBJECT_0) {
        std::fprintf(stderr, "console_ctrl_c: %s did not end within 60 s\n", argv[2]);
        TerminateProcess(process.hProcess, 3);
        return 3;
    }
    DWORD status = 0;
    GetExitCodeProcess(process.hProcess, &status);
    CloseHandle(process.hProcess);
    return static_cast<int>(status);
}
