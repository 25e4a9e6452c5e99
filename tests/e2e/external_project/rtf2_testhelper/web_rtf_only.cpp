// RTF 2.x's simple_web.cpp way: a program linking RTF only shows its run with
// WebProgressListener(port, verbose), and the page answers. Exit 0 when it did.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/WebProgressListener.h>

using namespace robottestingframework;

class Arithmetic : public TestCase {
public:
    Arithmetic() : TestCase("Arithmetic") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(6 * 7 == 42, "six times seven"); }
};

// The first line of the page's answer to GET /.
std::string statusLine(unsigned int port) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    std::string answer;
    if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        const std::string request =
            "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
        if (write(fd, request.data(), request.size()) == static_cast<ssize_t>(request.size())) {
            char buffer[256];
            const ssize_t got = read(fd, buffer, sizeof buffer);
            answer.assign(buffer, got > 0 ? static_cast<std::size_t>(got) : 0);
        }
    }
    close(fd);
    return answer.substr(0, answer.find('\r'));
}

int main() {
    WebProgressListener web(0, false);  // 0: a free port, so tests may run side by side
    TestResultCollector collector;
    TestResult result;
    result.addListener(&collector);
    result.addListener(&web);
    Arithmetic test;
    TestRunner runner;
    runner.addTest(&test);
    runner.run(result);
    const std::string status = statusLine(web.port());
    std::printf("%s answered: %s\n", web.url().c_str(), status.c_str());
    return web.isListening() && status == "HTTP/1.1 200 OK" && collector.passedCount() == 1 ? 0 : 1;
}
