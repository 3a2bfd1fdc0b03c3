// alp85: the ALP 85 emulator's command-line front end.
#include <cstdio>
#include <exception>
#include <string>

#include "asm/version.h"
#include "emu/cli/commands.h"

int main(int argc, char** argv) {
    CLI::App app{"ALP85: emulator of the ALP 85 Intel 8085 board"};
    app.require_subcommand(1);
    app.footer("Exit status: 0 success, 2 a usage error (unknown option, missing argument); each command's\n"
               "--help lists its own.");
    app.set_version_flag("--version", "alp85 " + std::string(alp85::version()),
                         "Print the version (and the git commit of the build) and exit");
    int status = 0;
    // In the order --help lists them.
    namespace cli = alp85::cli;
    for (auto* add : {cli::add_cpm_command, cli::add_bench_command, cli::add_disasm_command, cli::add_gcode_command,
                      cli::add_pisa_command, cli::add_run_command, cli::add_script_command, cli::add_gui_command,
                      cli::add_debug_command, cli::add_dap_command, cli::add_timing_command})
        add(app, status);

    alp85::cli::set_command_line(argc, argv);
    // CLI11 would say only "A subcommand is required": name the word that is not a command.
    if (argc > 1 && argv[1][0] != '-') {
        std::string names;
        bool known = false;
        for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
            known = known || sub->check_name(argv[1]);
            names += (names.empty() ? "" : ", ") + sub->get_name();
        }
        if (!known) {
            std::fputs(alp85::cli::argument_error("alp85", argv[1],
                                                  std::string("'") + argv[1] + "' is not a command (" + names + ")")
                           .c_str(),
                       stderr);
            return alp85::cli::kUsageError;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help is not an error; every usage error is 2, not CLI11's own codes (105, 106, ...).
        return app.exit(e) == 0 ? 0 : alp85::cli::kUsageError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "alp85: %s\n", e.what());
        return 1;
    }
    return status;
}
