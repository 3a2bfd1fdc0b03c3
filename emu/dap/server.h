// `alp85 dap`'s loop: messages from stdin (or one TCP client on 127.0.0.1) to the Adapter, its
// responses and events back, and the machine run in slices in between.
#pragma once

#include <cstdint>
#include <ostream>

namespace alp85::dap {

// Serves one session over the descriptors; returns when the client disconnects or the input
// ends. 0 after a disconnect, 1 when the input ended without one.
int serve(int in, int out);
// Listens on 127.0.0.1:port, serves the first client to connect, then returns (as serve). The
// port actually bound (port 0: any free one) is written to `announce` first. -1: could not listen.
int serve_tcp(std::uint16_t port, std::ostream& announce);

}  // namespace alp85::dap
