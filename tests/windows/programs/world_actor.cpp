// A process of the Windows process-fixture tests' worlds (e2e/test_windows_fixture_process.py),
// and the exec test that checks the world is up. Options, in this order of effect:
//   --pid-file FILE        writes its pid there
//   --child PROGRAM        starts PROGRAM (a child that stays: the job must end it too)
//   --child-pid-file FILE  writes that child's pid there
//   --delay SECONDS        sleeps before becoming ready
//   --listen PORT          listens on 127.0.0.1:PORT
//   --touch FILE           creates FILE
//   --print LINE           prints LINE (flushed)
//   --exit-after SECONDS   then exits with --exit-code (default: runs for 10 minutes)
//   --expect-file FILE, --expect-port PORT: checks that FILE exists and that 127.0.0.1:PORT
//   accepts a connection, prints the result as TAP and exits 0 or 1 (nothing else is done).
#include <winsock2.h>
// After winsock2.h, which must come first.
#include <windows.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

void writePid(const std::string& file, unsigned long pid) {
    if (!file.empty()) {
        std::ofstream(file) << pid << "\n";
    }
}

bool accepts(int port) {
    SOCKET s = ::socket(AF_INET, SOCK_STREAM, IPPROTO_TCP);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = ::htons(static_cast<u_short>(port));
    address.sin_addr.s_addr = ::htonl(INADDR_LOOPBACK);
    const bool connected =
        ::connect(s, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
    ::closesocket(s);
    return connected;
}

}  // namespace

int main(int argc, char** argv) {
    std::string pidFile, child, childPidFile, touch, print, expectFile;
    double delay = 0, exitAfter = -1;
    int port = 0, exitCode = 0, expectPort = 0;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string option = argv[i], value = argv[i + 1];
        if (option == "--pid-file") {
            pidFile = value;
        } else if (option == "--child") {
            child = value;
        } else if (option == "--child-pid-file") {
            childPidFile = value;
        } else if (option == "--delay") {
            delay = std::atof(value.c_str());
        } else if (option == "--listen") {
            port = std::atoi(value.c_str());
        } else if (option == "--touch") {
            touch = value;
        } else if (option == "--print") {
            print = value;
        } else if (option == "--exit-after") {
            exitAfter = std::atof(value.c_str());
        } else if (option == "--exit-code") {
            exitCode = std::atoi(value.c_str());
        } else if (option == "--expect-file") {
            expectFile = value;
        } else if (option == "--expect-port") {
            expectPort = std::atoi(value.c_str());
        } else {
            std::fprintf(stderr, "world_actor: unknown option %s\n", option.c_str());
            return 2;
        }
    }
    WSADATA data{};
    ::WSAStartup(MAKEWORD(2, 2), &data);
    if (!expectFile.empty() || expectPort != 0) {
        const bool file = expectFile.empty() ||
                          ::GetFileAttributesA(expectFile.c_str()) != INVALID_FILE_ATTRIBUTES;
        const bool listening = expectPort == 0 || accepts(expectPort);
        std::printf("1..2\n%s 1 - the file %s exists\n%s 2 - port %d accepts\n",
                    file ? "ok" : "not ok", expectFile.c_str(), listening ? "ok" : "not ok",
                    expectPort);
        std::fflush(stdout);
        return file && listening ? 0 : 1;
    }
    writePid(pidFile, ::GetCurrentProcessId());
    if (!child.empty()) {
        STARTUPINFOA startup{};
        startup.cb = sizeof(startup);
        PROCESS_INFORMATION info{};
        std::string command = "\"" + child + "\"";
        if (::CreateProcessA(nullptr, &command[0], nullptr, nullptr, FALSE, 0, nullptr, nullptr,
                             &startup, &info)) {
            writePid(childPidFile, info.dwProcessId);
            ::CloseHandle(info.hThread);
            ::CloseHandle(info.hProcess);
        }
    }
    std::printf("starting\n");
    std::fflush(stdout);
    ::Sleep(static_cast<DWORD>(delay * 1000));
    if (port != 0) {
        SOCKET listener = ::socket(AF_INET, SOCK_STREAM, IPPROTO_TCP);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = ::htons(static_cast<u_short>(port));
        address.sin_addr.s_addr = ::htonl(INADDR_LOOPBACK);
        if (::bind(listener, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 ||
            ::listen(listener, 16) != 0) {
            std::printf("cannot listen on port %d: error %d\n", port, ::WSAGetLastError());
            std::fflush(stdout);
            return 3;
        }
    }
    if (!touch.empty()) {
        std::ofstream(touch) << "ready\n";
    }
    if (!print.empty()) {
        std::printf("%s\n", print.c_str());
        std::fflush(stdout);
    }
    if (exitAfter >= 0) {
        ::Sleep(static_cast<DWORD>(exitAfter * 1000));
        std::printf("giving up with status %d\n", exitCode);
        std::fflush(stdout);
        return exitCode;
    }
    ::Sleep(600000);
    return 0;
}
