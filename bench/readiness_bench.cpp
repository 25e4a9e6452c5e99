// rtf-bench-readiness: how soon the process fixture sees a port open. Each run starts a server
// that opens its TCP port 300 ms after it starts and prints the moment it did (the system's
// monotonic clock); the delay is from that moment to the fixture's start() returning ready.
//   rtf-bench-readiness [--runs N] [--folder DIR]
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "fixtures/process/process_supervisor.h"
#include "fixtures/process/world_file.h"

using namespace robottestingframework::fixtures;

namespace {

int freePort() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
    socklen_t size = sizeof address;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size);
    ::close(fd);
    return ntohs(address.sin_port);
}

const char* kServer =
    "import socket, sys, time\n"
    "time.sleep(0.3)\n"
    "s = socket.socket()\n"
    "s.bind(('127.0.0.1', int(sys.argv[1])))\n"
    "s.listen()\n"
    "print(repr(time.clock_gettime(time.CLOCK_MONOTONIC)), flush=True)\n"
    "time.sleep(60)\n";

}  // namespace

int main(int argc, char** argv) {
    int runs = 50;
    std::filesystem::path folder = std::filesystem::temp_directory_path() / "rtf-bench-readiness";
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--runs") == 0) {
            runs = std::max(1, std::atoi(argv[i + 1]));
        } else if (std::strcmp(argv[i], "--folder") == 0) {
            folder = argv[i + 1];
        }
    }
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "server.py") << kServer;

    std::vector<double> delays;
    for (int run = 0; run < runs; ++run) {
        const int port = freePort();
        const std::string text =
            "<world name='bench'><process name='server' command='/usr/bin/python3 server.py " +
            std::to_string(port) + "'><ready timeout='10s'><port>" + std::to_string(port) +
            "</port></ready></process></world>";
        WorldOptions options;
        options.logFolder = (folder / "logs").string();
        World world;
        std::string error;
        if (!parseWorld(text, (folder / "world.xml").string(), options, world, error)) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return 2;
        }
        const std::string log = world.processes[0].logFile;
        ProcessSupervisor supervisor(world);
        if (!supervisor.start([](const std::string&) {}, error)) {
            std::fprintf(stderr, "run %d: %s\n", run + 1, error.c_str());
            return 1;
        }
        const double ready = monotonicSeconds();
        double opened = 0;
        for (int i = 0; i < 1000 && opened == 0; ++i) {
            std::ifstream in(log);
            in >> opened;
            if (opened == 0) {
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
        }
        supervisor.stop([](const std::string&) {});
        if (opened == 0) {
            std::fprintf(stderr, "run %d: the server did not say when it listened\n", run + 1);
            return 1;
        }
        delays.push_back((ready - opened) * 1000);
    }

    std::sort(delays.begin(), delays.end());
    const std::size_t n = delays.size();
    const double median = n % 2 ? delays[n / 2] : (delays[n / 2 - 1] + delays[n / 2]) / 2;
    const double worst = delays.back();
    std::printf(
        "readiness latency: port opened -> fixture ready, %zu runs (port opened 300 ms "
        "after start)\n",
        n);
    std::printf("  %-8s %8.2f ms   target <= 5 ms    %s\n", "median", median,
                median <= 5 ? "ok" : "MISSED");
    std::printf("  %-8s %8.2f ms   target <= 20 ms   %s\n", "worst", worst,
                worst <= 20 ? "ok" : "MISSED");
    std::printf("  %-8s %8.2f ms\n", "best", delays.front());
    return 0;
}
