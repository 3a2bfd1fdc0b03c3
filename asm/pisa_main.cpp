// pisa-asm: the command line of the Pisa interpolator's assembler (asm/pisa_asm.h).
#include <iostream>

#include <CLI/CLI.hpp>

#include "asm/pisa_asm.h"
#include "asm/version.h"
#include "asm/files/atomic_file.h"
#include "asm/files/output_paths.h"

int main(int argc, char** argv) {
    using namespace alp85;
    CLI::App app{"pisa-asm: assembler of the Pisa multi-purpose interpolator (CNR-IEI, 1969)", "pisa-asm"};
    std::string source, rom_out, lst_out, map_out;
    std::vector<std::string> defines;
    bool no_rom = false;
    app.add_option("SOURCE", source, "Assembly source (.pasm)")->required();
    CLI::Option* rom_opt =
        app.add_option("-o,--rom", rom_out, "ROM image, one word a line: address and octal word (default SOURCE.rom)");
    app.add_flag("--no-rom", no_rom, "Write no ROM image (only the other outputs asked for)");
    CLI::Option* lst_opt = app.add_option("--lst", lst_out, "Listing output");
    CLI::Option* map_opt = app.add_option("--map", map_out, "JSON map output (symbols, word -> source line)");
    app.add_option("-D,--define", defines, "Define NAME or NAME=VALUE before assembly (NAME a symbol's name, VALUE an expression)");
    app.set_version_flag("--version", "pisa-asm " + std::string(alp85::version()),
                         "Print the version (and the git commit of the build) and exit");
    app.footer("Diagnostics are written as file:line:col: error: message.\n"
               "Exit status: 0 success; 1 an error in the source or an output that cannot be written (then no\n"
               "output file is written); 2 a usage error (an empty output name, an output that is the source,\n"
               "two outputs on one file, a bad -D: a NAME that is not a name or a VALUE that is not an\n"
               "expression; nothing is written).");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    // An empty output name names no file: refused, not taken for the default or for "no output".
    const std::pair<const CLI::Option*, const std::string*> given[] = {{rom_opt, &rom_out}, {lst_opt, &lst_out}, {map_opt, &map_out}};
    for (const auto& [o, path] : given)
        if (o->count() > 0 && path->empty()) {
            std::cerr << "pisa-asm: error: " << o->get_name(false, true) << " '': an empty file name; nothing written\n";
            return 2;
        }
    pisa_asm::Options opt;
    for (auto& d : defines) {
        auto eq = d.find('=');
        opt.defines.emplace_back(d.substr(0, eq), eq == std::string::npos ? "" : d.substr(eq + 1));
    }
    if (rom_out.empty() && !no_rom) rom_out = std::filesystem::path(source).replace_extension(".rom").string();
    if (no_rom) rom_out.clear();
    const std::vector<NamedPath> outs = {{rom_out, "-o"}, {lst_out, "--lst"}, {map_out, "--map"}};
    if (const std::string clash = output_clash({{source, "the source"}}, outs); !clash.empty()) {
        std::cerr << "pisa-asm: error: " << clash << "; nothing written\n";
        return 2;
    }
    if (!opt.defines.empty()) {  // a -D whose value is not an expression: a usage error
        const auto d = pisa_asm::assemble_string("", opt, "<command line>");
        if (!d.ok()) {
            for (const auto& diag : d.out.diagnostics)
                if (diag.severity == asm85::Severity::Error) std::cerr << "pisa-asm: error: " << diag.message << '\n';
            std::cerr << "pisa-asm: a bad -D; nothing written\n";
            return 2;
        }
    }
    auto r = pisa_asm::assemble_file(source, opt);
    for (auto& d : r.out.diagnostics) std::cerr << asm85::format_diagnostic(d);
    if (!r.ok()) {
        std::cerr << "pisa-asm: " << r.out.error_count() << (r.out.error_count() == 1 ? " error" : " errors")
                  << ", no output written\n";
        return 1;
    }
    AtomicFileGroup outputs;
    if (!rom_out.empty()) outputs.add(rom_out, pisa_asm::write_rom_text(r));
    if (!lst_out.empty()) outputs.add(lst_out, asm85::write_listing(r.out, pisa_asm::output_format()));
    if (!map_out.empty()) outputs.add(map_out, asm85::write_json_map(r.out, pisa_asm::output_format()));
    try {
        outputs.commit();
    } catch (const std::exception& e) {
        std::cerr << "pisa-asm: error: " << e.what() << "; no output written\n";
        return 1;
    }
    return 0;
}
