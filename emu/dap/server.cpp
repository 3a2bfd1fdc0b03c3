#include "emu/dap/server.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <deque>
#include <optional>
#include <string>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "emu/dap/adapter.h"
#include "emu/dap/framing.h"

namespace alp85::dap {

namespace {
bool is_pause(const std::string& body) {
    const Json msg = Json::parse(body, nullptr, /*allow_exceptions=*/false);
    return msg.is_object() && msg.contains("type") && msg["type"] == "request" && msg.contains("command") &&
           msg["command"] == "pause";
}
}  // namespace

int serve(int in, int out) {
    std::signal(SIGPIPE, SIG_IGN);  // a client that goes away ends the session, not the process
    Channel channel(in, out);
    bool peer_gone = false;
    Adapter adapter([&](const Json& message) {
        if (!channel.send(message.dump(-1, ' ', false, Json::error_handler_t::replace))) peer_gone = true;
    });
    // A reverse run holds this thread while it re-executes the past: between its slices the
    // messages that came are read and kept, in order, for after it; a pause among them ends it.
    std::deque<Frame> early;
    bool input_ended = false;
    adapter.set_poll([&] {
        if (!input_ended && !channel.fill(0)) input_ended = true;
        while (auto f = channel.next()) {
            if (f->error.empty() && is_pause(f->body)) adapter.interrupt();
            early.push_back(std::move(*f));
        }
    });
    const auto next_frame = [&]() -> std::optional<Frame> {
        if (early.empty()) return channel.next();
        Frame f = std::move(early.front());
        early.pop_front();
        return f;
    };
    int pace = 0;  // ms the last slice ran ahead of the host's clock (real-time runs)
    while (!adapter.finished() && !peer_gone) {
        // Messages first: a run never delays a pause by more than one slice.
        while (auto f = next_frame()) {
            if (f->error.empty()) adapter.receive(f->body);
            else adapter.refuse_frame(f->error);
            if (adapter.finished()) return 0;
        }
        if (input_ended || !channel.fill(adapter.running() ? pace : -1)) return adapter.finished() ? 0 : 1;
        pace = adapter.running() ? std::max(0, adapter.advance()) : 0;
    }
    return adapter.finished() ? 0 : 1;
}

int serve_tcp(std::uint16_t port, std::ostream& announce) {
    const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
    if (listener < 0) return -1;
    const int one = 1;
    ::setsockopt(listener, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // loopback only: a debugger is no network service
    if (::bind(listener, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0 || ::listen(listener, 1) < 0) {
        ::close(listener);
        return -1;
    }
    socklen_t len = sizeof addr;
    ::getsockname(listener, reinterpret_cast<sockaddr*>(&addr), &len);
    announce << "alp85 dap: listening on 127.0.0.1:" << ntohs(addr.sin_port) << std::endl;
    int client = -1;
    do client = ::accept(listener, nullptr, nullptr);
    while (client < 0 && errno == EINTR);
    ::close(listener);
    if (client < 0) return -1;
    const int status = serve(client, client);
    ::close(client);
    return status;
}

}  // namespace alp85::dap
