// alp85 dap [--port N]: a Debug Adapter Protocol server for editors (docs/editors.md), over
// stdin/stdout or one TCP client on 127.0.0.1.
#include <iostream>
#include <memory>

#include <unistd.h>

#include "emu/cli/commands.h"
#include "emu/dap/server.h"

namespace alp85::cli {

void add_dap_command(CLI::App& app, int& status) {
    auto port = std::make_shared<int>(-1);
    CLI::App* cmd = app.add_subcommand("dap", "Debug Adapter Protocol server: debug firmware from VS Code, Neovim, Emacs");
    cmd->add_option("--port", *port, "Serve one client on 127.0.0.1:PORT instead of stdin/stdout (0: any free port, announced on stderr)")
        ->check(CLI::Range(0, 65535));
    cmd->footer(
        "The launch configuration names the firmware (program: a .asm assembled with its line map, or\n"
        "firmware: thesis-fixed), keys to type, stopOnEntry, motor; docs/editors.md.\n"
        "Exit status: 0 the client disconnected, 1 the input ended without a disconnect or the port\n"
        "could not be opened, 2 a usage error.");
    cmd->callback([port, &status] {
        if (*port < 0) {
            status = dap::serve(STDIN_FILENO, STDOUT_FILENO);
            return;
        }
        const int r = dap::serve_tcp(static_cast<std::uint16_t>(*port), std::cerr);
        if (r < 0) std::cerr << "alp85 dap: cannot listen on 127.0.0.1:" << *port << "\n";
        status = r < 0 ? 1 : r;
    });
}

}  // namespace alp85::cli
