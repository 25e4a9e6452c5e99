// The HTTP side of the live page: serves the page and the run's RunView over cpp-httplib on a
// thread of its own, until stop() or destruction.
#pragma once

#include <memory>
#include <string>
#include <thread>

#include "web/run_view.h"

namespace httplib {
class Server;
}

namespace robottestingframework {
namespace web {

class WebServer {
public:
    explicit WebServer(const RunView& view);
    ~WebServer();
    WebServer(const WebServer&) = delete;
    WebServer& operator=(const WebServer&) = delete;

    // Binds host:port (0: a free port) and serves; false with `error` set when it cannot.
    bool start(const std::string& host, unsigned int port, std::string& error);
    // The bound port.
    unsigned int port() const { return port_; }
    // Stops serving and waits for the server's threads. The view must be closed first, or an
    // event stream keeps its connection up to a second longer.
    void stop();

private:
    bool allowedHost(const std::string& host) const;

    const RunView& view_;
    std::unique_ptr<httplib::Server> server_;
    std::thread thread_;
    std::string host_;
    unsigned int port_ = 0;
};

}  // namespace web
}  // namespace robottestingframework
