// Connects to the simulated robot (started by the process fixture) and checks its joint states:
// a JSON line arrives at once, it names every joint, and the stream moves.
// Param: --port N (the robot's port on 127.0.0.1).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class JointStatesTest : public TestCase {
public:
    JointStatesTest() : TestCase("JointStatesTest") {}

    bool setup(int argc, char** argv) override {
        std::string port;
        if (Arguments::getOption(argc, argv, "--port", port)) {
            port_ = std::stoi(port);
        }
        fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
        timeval timeout{2, 0};
        ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = htons(static_cast<uint16_t>(port_));
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(
            ::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0,
            Asserter::format("cannot connect to the robot on 127.0.0.1:%d", port_));
        return true;
    }

    void run() override {
        const std::string first = readLine();
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("first joint state: " + first.substr(0, 120) + "...");
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_FALSE(!first.empty(), "the robot sends its state");
        for (const char* joint : {"shoulder_pitch", "shoulder_roll", "shoulder_yaw", "elbow",
                                  "wrist_pitch", "wrist_yaw"}) {
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(
                first.find('"' + std::string(joint) + '"') != std::string::npos,
                std::string("the state names joint ") + joint);
        }
        // The rate the robot sends its states at, from the times they carry (what the socket
        // buffered meanwhile does not count): it promises 100 Hz.
        std::string later;
        double firstTime = -1;
        double lastTime = -1;
        for (int i = 0; i < 20; ++i) {
            later = readLine();
            const double time = timeOf(later);
            firstTime = firstTime < 0 ? time : firstTime;
            lastTime = time;
        }
        const double span = lastTime - firstTime;
        ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN("message rate", span > 0 ? 19 / span : 0.0, "Hz", 20,
                                              500);
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(!later.empty() && later != first,
                                         "the joints move (a later state differs)");
    }

    void tearDown() override {
        if (fd_ >= 0) {
            ::close(fd_);
            fd_ = -1;
        }
    }

private:
    // The "time" a state line carries (seconds since the robot started); -1 without one.
    static double timeOf(const std::string& line) {
        const std::size_t at = line.find("\"time\": ");
        return at == std::string::npos ? -1 : std::strtod(line.c_str() + at + 8, nullptr);
    }

    std::string readLine() {
        std::string line;
        char c = 0;
        while (::read(fd_, &c, 1) == 1 && c != '\n') {
            line += c;
        }
        return line;
    }

    int port_ = 18831;
    int fd_ = -1;
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(JointStatesTest)
