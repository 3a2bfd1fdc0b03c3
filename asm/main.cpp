// asm85: the command-line front end of the assembler library.
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "asm/asm85.h"
#include "asm/lexer.h"
#include "asm/version.h"
#include "asm/files/atomic_file.h"
#include "asm/files/output_paths.h"

namespace {

using namespace alp85::asm85;

constexpr const char* kExamples = R"(Examples:
  asm85 monitor.asm                      writes monitor.hex
  asm85 prog.asm -o prog.hex --lst prog.lst --map prog.json
  asm85 bdos.asm --bin bdos.bin --bin-start 0E800H --bin-end 0F5FFH --fill 0
  asm85 test.asm --cpu 8085u -D DEBUG -D BAUD=9600 -I include/
Diagnostics are written as file:line:col: error: message.
Exit status: 0 success; 1 an error in the source (or a source that cannot be read) or an output
that cannot be written, and then no output file is written; 2 a usage error (an unknown option,
a bad --cpu, --bin-start, --bin-end, --fill or -D, an empty output name, an output that is the
source or an INCLUDEd file, two outputs on one file), and nothing is written either.)";

constexpr int kUsageError = 2;

// 0x1F, 1FH, 31: what a user may type for an address.
std::optional<std::uint32_t> parse_address(const std::string& s) {
    std::uint32_t v = 0;
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        if (!parse_number(s.substr(2) + "H", 10, v)) return std::nullopt;
    } else if (!parse_number(s, 10, v)) {
        return std::nullopt;
    }
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"asm85: Intel 8080/8085 macro assembler (Intel ASM80, DR ASM/MAC and M80 dialects)", "asm85"};
    std::string source, hex_out, bin_out, lst_out, map_out, cpu = "8085", bin_start, bin_end, fill = "0";
    std::vector<std::string> defines, includes;
    bool quiet = false, no_unused = false, no_hex = false;
    int name_length = 0;
    app.add_option("SOURCE", source, "Assembly source file")->required();
    CLI::Option* hex_opt = app.add_option("-o,--hex", hex_out, "Intel HEX output (default: SOURCE with .hex)");
    app.add_flag("--no-hex", no_hex, "Write no Intel HEX file (only the other outputs asked for)");
    CLI::Option* bin_opt = app.add_option("--bin", bin_out, "Raw binary output");
    app.add_option("--bin-start", bin_start, "First address of the binary (default: lowest emitted)");
    app.add_option("--bin-end", bin_end, "Last address of the binary (default: highest emitted)");
    app.add_option("--fill", fill, "Byte for gaps in the binary (default 0)");
    CLI::Option* lst_opt = app.add_option("--lst", lst_out, "Listing output");
    CLI::Option* map_opt = app.add_option("--map", map_out, "JSON map output (symbols, byte -> source line)");
    app.add_option("-D,--define", defines, "Define NAME or NAME=VALUE before assembly");
    app.add_option("-I,--include", includes, "Directory searched by INCLUDE and MACLIB");
    app.add_option("--cpu", cpu, "8080, 8085 (default) or 8085u (8085 with its undocumented instructions)")
        ->check(CLI::IsMember({"8080", "8085", "8085u", "8085U"}));
    app.add_option("--name-length", name_length, "Significant characters of a name (6 for Intel ASM80/M80 sources; default all)")
        ->check(CLI::Range(0, 64));
    app.add_flag("-q,--quiet", quiet, "Print errors only, no warnings");
    app.add_flag("--no-unused-macro-warnings", no_unused, "Don't warn about macros that are never used");
    app.set_version_flag("--version", "asm85 " + std::string(alp85::version()),
                         "Print the version (and the git commit of the build) and exit");
    app.footer(kExamples);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : kUsageError;  // --help is no error; not CLI11's codes (105, 106)
    }
    // An output option given an empty name names no file: refused, not taken for "the default"
    // (-o '' would write SOURCE.hex) or "no output" (--lst '').
    const std::pair<const CLI::Option*, const std::string*> given[] = {
        {hex_opt, &hex_out}, {bin_opt, &bin_out}, {lst_opt, &lst_out}, {map_opt, &map_out}};
    for (const auto& [o, path] : given)
        if (o->count() > 0 && path->empty()) {
            std::cerr << "asm85: error: " << o->get_name(false, true) << " '': an empty file name; nothing written\n";
            return kUsageError;
        }

    Options opt;
    opt.cpu = *parse_cpu(cpu);
    opt.warn_unused_macros = !no_unused;
    opt.name_length = name_length;
    for (auto& d : defines) {
        auto eq = d.find('=');
        opt.defines.emplace_back(d.substr(0, eq), eq == std::string::npos ? "" : d.substr(eq + 1));
    }
    for (auto& i : includes) opt.include_dirs.emplace_back(i);

    if (hex_out.empty() && !no_hex) hex_out = std::filesystem::path(source).replace_extension(".hex").string();
    if (no_hex) hex_out.clear();
    // An output on an input (or on another output) is refused before anything is read or written.
    const std::vector<alp85::NamedPath> outs = {{hex_out, "-o"}, {bin_out, "--bin"}, {lst_out, "--lst"}, {map_out, "--map"}};
    if (const std::string clash = alp85::output_clash({{source, "the source"}}, outs); !clash.empty()) {
        std::cerr << "asm85: error: " << clash << "; nothing written\n";
        return kUsageError;
    }
    // A -D whose value is not an expression is a usage error, named as the user typed it.
    if (!opt.defines.empty()) {
        const Result d = assemble_string("", opt, "<command line>");
        if (!d.ok()) {
            for (const auto& diag : d.diagnostics)
                if (diag.severity == Severity::Error) std::cerr << "asm85: error: " << diag.message << '\n';
            std::cerr << "asm85: a bad -D; nothing written\n";
            return kUsageError;
        }
    }

    Result r = assemble_file(source, opt);
    bool shown = true;  // a note goes with the diagnostic before it
    for (auto& d : r.diagnostics) {
        if (d.severity != Severity::Note) shown = !quiet || d.severity == Severity::Error;
        if (shown) std::cerr << format_diagnostic(d);
    }
    if (!r.ok()) {
        std::cerr << "asm85: " << r.error_count() << (r.error_count() == 1 ? " error" : " errors") << ", no output written\n";
        return 1;
    }

    std::optional<std::uint32_t> first, last, fillv = parse_address(fill);
    if (!bin_start.empty() && !(first = parse_address(bin_start))) {
        std::cerr << "asm85: error: bad --bin-start '" << bin_start << "'\n";
        return kUsageError;
    }
    if (!bin_end.empty() && !(last = parse_address(bin_end))) {
        std::cerr << "asm85: error: bad --bin-end '" << bin_end << "'\n";
        return kUsageError;
    }
    if (!fillv || *fillv > 0xFF || (first && *first > 0xFFFF) || (last && *last > 0xFFFF)) {
        std::cerr << "asm85: error: --fill must be a byte and addresses at most 0FFFFH\n";
        return kUsageError;
    }

    std::vector<alp85::NamedPath> inputs;
    for (std::size_t i = 1; i < r.files.size(); ++i) inputs.push_back({r.files[i], "the INCLUDEd file"});
    if (const std::string clash = alp85::output_clash(inputs, outs); !clash.empty()) {
        std::cerr << "asm85: error: " << clash << "; nothing written\n";
        return kUsageError;
    }
    // Every output is made first, then all are written together or none is (make relies on it).
    alp85::AtomicFileGroup outputs;
    if (!hex_out.empty()) outputs.add(hex_out, write_intel_hex(r.image));
    if (!bin_out.empty()) {
        std::uint16_t lo = first ? static_cast<std::uint16_t>(*first) : r.image.empty() ? 0 : r.image.lowest();
        std::uint16_t hi = last ? static_cast<std::uint16_t>(*last) : r.image.empty() ? 0 : r.image.highest();
        if (r.image.empty() && !first && !last) {
            outputs.add(bin_out, "");
        } else if (hi < lo) {
            std::cerr << "asm85: error: --bin-end is below --bin-start; no output written\n";
            return kUsageError;
        } else {
            // Bytes the window leaves out: said, so that a ROM image cut short is not a surprise.
            std::size_t outside = 0;
            std::optional<std::uint16_t> first_out;
            for (const Segment& s : r.image.segments())
                for (std::uint32_t a = s.start; a < s.end(); ++a)
                    if (a < lo || a > hi) {
                        ++outside;
                        if (!first_out) first_out = static_cast<std::uint16_t>(a);
                    }
            if (outside)
                std::cerr << fmt::format("asm85: warning: {} byte{} outside the binary's {:04X}H-{:04X}H left out of {} "
                                         "(the first at {:04X}H; --bin-start and --bin-end set the range)\n",
                                         outside, outside == 1 ? "" : "s", lo, hi, bin_out, *first_out);
            auto bytes = write_binary(r.image, lo, hi, static_cast<std::uint8_t>(*fillv));
            outputs.add(bin_out, std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        }
    }
    if (!lst_out.empty()) outputs.add(lst_out, write_listing(r));
    if (!map_out.empty()) outputs.add(map_out, write_json_map(r));
    try {
        outputs.commit();
    } catch (const std::exception& e) {
        std::cerr << "asm85: error: " << e.what() << "; no output written\n";
        return 1;
    }
    return 0;
}
