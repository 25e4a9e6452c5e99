#include "web/web_server.h"

#include <cctype>
#include <chrono>
#include <fstream>
#include <sstream>

#include <httplib.h>

#include "web/exclusive_port.h"
#include "web/page_assets.h"
#include "web/socket_error.h"
#include "web/whole_answer.h"

namespace robottestingframework {
namespace web {

namespace {

// Sent with every answer: the page runs only its own script and style, talks only to this
// server, cannot be framed; nothing is cached or sniffed.
const char* const contentSecurityPolicy =
    "default-src 'none'; script-src 'self'; style-src 'self'; connect-src 'self'; "
    "img-src 'self'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'";

// "127.0.0.1:8080" -> "127.0.0.1", "[::1]:8080" -> "[::1]".
std::string hostName(const std::string& header) {
    if (!header.empty() && header[0] == '[') {
        std::size_t close = header.find(']');
        return close == std::string::npos ? header : header.substr(0, close + 1);
    }
    return header.substr(0, header.find(':'));
}

bool isIpLiteral(const std::string& host) {
    if (!host.empty() && host[0] == '[') {
        return true;
    }
    return !host.empty() && host.find_first_not_of("0123456789.") == std::string::npos;
}

std::uint64_t numberOr(const std::string& text, std::uint64_t fallback) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos ||
        text.size() > 18) {
        return fallback;
    }
    return std::stoull(text);
}

}  // namespace

WebServer::WebServer(const RunView& view) : view_(view), server_(new httplib::Server) {}

WebServer::~WebServer() {
    stop();
}

bool WebServer::allowedHost(const std::string& header) const {
    std::string host = hostName(header);
    for (auto& c : host) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    if (host == "localhost" || host == "127.0.0.1" || host == "[::1]") {
        return true;
    }
    if (host == host_ || host == "[" + host_ + "]") {
        return true;
    }
    // Bound to every address: any address may be asked for, but no name (DNS rebinding).
    return (host_ == "0.0.0.0" || host_ == "::") && isIpLiteral(host);
}

bool WebServer::start(const std::string& host, unsigned int port, std::string& error) {
    host_ = host;
    httplib::Server& server = *server_;
    // Each open page holds a thread for its event stream.
    server.new_task_queue = [] { return new httplib::ThreadPool(16); };
    server.set_socket_options(
        [](socket_t sock) { claimPortAlone(static_cast<std::uintptr_t>(sock)); });
    server.set_keep_alive_timeout(2);
    server.set_payload_max_length(0);
    server.set_default_headers({{"Content-Security-Policy", contentSecurityPolicy},
                                {"X-Content-Type-Options", "nosniff"},
                                {"X-Frame-Options", "DENY"},
                                {"Referrer-Policy", "no-referrer"},
                                {"Cache-Control", "no-store"}});
    server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
        if (req.method != "GET") {
            res.status = 405;
            res.set_header("Allow", "GET");
            res.set_content("only GET is answered\n", "text/plain");
            return httplib::Server::HandlerResponse::Handled;
        }
        if (!req.has_header("Host")) {
            if (req.version == "HTTP/1.0") {
                return httplib::Server::HandlerResponse::Unhandled;  // old clients send none
            }
            res.status = 400;
            res.set_content("no Host header\n", "text/plain");
            return httplib::Server::HandlerResponse::Handled;
        }
        if (!allowedHost(req.get_header_value("Host"))) {
            res.status = 403;
            res.set_content("this page is served to 127.0.0.1 and localhost only\n", "text/plain");
            return httplib::Server::HandlerResponse::Handled;
        }
        return httplib::Server::HandlerResponse::Unhandled;
    });

    auto asset = [&server](const char* path, const std::string& body, const char* type) {
        server.Get(path, [&body, type](const httplib::Request&, httplib::Response& res) {
            res.set_content(body, type);
        });
    };
    asset("/", pageHtml(), "text/html; charset=utf-8");
    asset("/index.html", pageHtml(), "text/html; charset=utf-8");
    asset("/page.js", pageJs(), "text/javascript; charset=utf-8");
    asset("/page.css", pageCss(), "text/css; charset=utf-8");
    server.Get("/snapshot", [this](const httplib::Request&, httplib::Response& res) {
        res.set_content(view_.snapshotJson(), "application/json");
    });
    // Only the files the run attached, by their number: no path from the request is opened.
    server.Get(R"(/attachments/(\d{1,9}))", [this](const httplib::Request& req,
                                                   httplib::Response& res) {
        RunView::AttachmentView attachment;
        std::ifstream file;
        if (view_.attachment(std::stoul(req.matches[1].str()), attachment)) {
            file.open(attachment.absolutePath, std::ios::binary);
        }
        if (!file.is_open()) {
            res.status = 404;
            res.set_content("no such attachment\n", "text/plain");
            return;
        }
        std::ostringstream bytes;
        bytes << file.rdbuf();
        res.set_header("Content-Disposition",
                       attachment.contentType.rfind("image/", 0) == 0 ? "inline" : "attachment");
        res.set_content(bytes.str(), attachment.contentType.c_str());
    });
    // RTF 2.x's protocol, as its clients read it (RTF 2.0.1's own WebProgListener test): one
    // read of at most 255 bytes must hold the whole answer, whose JSON line ends with "\r\n".
    // So the headers meant for the page are left out here, the body is the line, and the
    // answer to an HTTP/1.0 request, which closes the connection, leaves in one piece.
    server.Get("/status", [this](const httplib::Request& req, httplib::Response& res) {
        for (const char* pageOnly :
             {"Content-Security-Policy", "X-Frame-Options", "Referrer-Policy"}) {
            res.headers.erase(pageOnly);
        }
        res.set_content(view_.statusJson() + "\r\n", "application/json");
        if (req.version == "HTTP/1.0" && req.get_header_value("Connection") != "keep-alive") {
            holdAnswerUntilClosed(req.local_addr, req.local_port, req.remote_addr, req.remote_port);
        }
    });
    server.Get("/update", [this](const httplib::Request&, httplib::Response& res) {
        res.set_content(view_.logText(), "text/plain; charset=utf-8");
    });
    server.Get("/events", [this](const httplib::Request& req, httplib::Response& res) {
        // A reconnecting EventSource sends Last-Event-ID; a page starts from its snapshot.
        std::uint64_t since = numberOr(req.get_param_value("since"), 0);
        since = numberOr(req.get_header_value("Last-Event-ID"), since);
        res.set_chunked_content_provider(
            "text/event-stream", [this, since](std::size_t, httplib::DataSink& sink) mutable {
                std::string out;
                bool closed = false;
                since = view_.waitForChanges(since, std::chrono::milliseconds(1000), out, closed);
                if (out.empty()) {
                    out = ": still here\n\n";  // finds a closed connection
                }
                if (!sink.write(out.data(), out.size())) {
                    return false;
                }
                if (closed) {
                    sink.done();
                }
                return true;
            });
    });

    clearSocketError();
    if (port == 0) {
        int bound = server.bind_to_any_port(host);
        if (bound <= 0) {
            error = std::string("cannot listen on ") + host + ": " +
                    socketError("the address is not available");
            return false;
        }
        port_ = static_cast<unsigned int>(bound);
    } else {
        if (!server.bind_to_port(host, static_cast<int>(port))) {
            error = "cannot listen on " + host + ":" + std::to_string(port) + ": " +
                    socketError("the address is not available");
            return false;
        }
        port_ = port;
    }
    thread_ = std::thread([&server] { server.listen_after_bind(); });
    // stop() does nothing to a server that is not running yet, so wait until it is.
    while (!server.is_running()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

void WebServer::stop() {
    if (thread_.joinable()) {
        server_->stop();
        thread_.join();
    }
}

}  // namespace web
}  // namespace robottestingframework
