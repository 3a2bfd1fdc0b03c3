// alp85 disasm IMAGE|--monitor [--org A] [--from A] [--to A] [--map FILE]... [--cpu 8080|8085]
//              [--source] [-o FILE]
// Disassembles a program image as a listing, or as asm85 source that assembles back to the same
// bytes (emu/program/disasm_listing.h).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "asm/files/atomic_file.h"
#include "emu/cli/commands.h"
#include "emu/program/disasm_listing.h"
#include "emu/program/firmware.h"
#include "emu/program/image_loader.h"
#include "emu/script/parser.h"

namespace alp85::cli {

namespace {

struct DisasmArgs {
    std::string image;
    bool monitor = false;
    std::string org, from, to;
    std::vector<std::string> maps;
    bool no_symbols = false;
    std::string cpu = "8085";
    bool source = false;
    std::string output;
};

// 0800H, 0x800, 2048 (the script language's numbers), or a symbol's name.
std::optional<std::uint16_t> parse_address(const std::string& text, const SymbolTable& symbols, std::string& error) {
    if (std::string why = script::ambiguous_address(text); !why.empty()) {
        error = std::move(why);
        return std::nullopt;
    }
    if (const auto n = script::parse_number(text)) {
        if (*n >= 0 && *n <= 0xFFFF) return static_cast<std::uint16_t>(*n);
        error = fmt::format("'{}' is not an address (0000H-0FFFFH; e.g. 0800H, 0x800, 2048 or a symbol)", text);
        return std::nullopt;
    }
    if (auto v = symbols.value_of(text)) return v;
    error = fmt::format("'{}' is neither an address nor a known symbol", text);
    return std::nullopt;
}

int run_disasm(const DisasmArgs& args) {
    const auto fail = [](const std::string& message, int status) {
        std::cerr << "alp85 disasm: " << message << '\n';
        return status;
    };
    if (args.monitor == !args.image.empty()) return fail("give either an image file or --monitor", 2);
    {
        std::vector<NamedPath> inputs = {{args.image, "the image"}};
        for (const std::string& m : args.maps) inputs.push_back({m, "the map"});
        if (refuse_output_clash("disasm", inputs, {{args.output, "-o"}})) return 2;
    }
    if (!args.image.empty())
        if (const std::string why = input_file_problem(args.image); !why.empty()) return fail(why, 1);

    SymbolTable symbols;
    std::vector<ImageSegment> segments;
    std::string origin;
    if (args.monitor) {
        if (!firmware::have_monitor()) return fail("this alp85 was built without the monitor ROM", 2);
        segments = firmware::monitor().segments;
        if (!args.no_symbols) symbols.load_map_text(firmware::monitor_map());
        origin = "the built-in monitor ROM";
    } else {
        std::string error;
        LoadOptions lo;
        if (!args.org.empty()) {
            lo.address = parse_address(args.org, symbols, error);
            if (!lo.address) return fail("--org: " + error, 2);
        }
        try {
            LoadedImage img = read_image(args.image, lo);
            for (const std::string& w : img.warnings) std::cerr << w;
            segments = std::move(img.segments);
            if (!args.no_symbols)
                for (const asm85::Symbol& s : img.symbols) symbols.add(s.name, s.value, asm85::kind_name(s.kind));
        } catch (const LoadError& e) {
            return fail(e.what(), 1);
        }
        origin = args.image;
    }
    if (!args.no_symbols)
        for (const std::string& m : args.maps)
            if (const std::string err = symbols.load_map_file(m); !err.empty()) return fail(err, 1);

    ImageDisasmOptions o;
    o.variant = variant_of(args.cpu);
    o.symbols = args.no_symbols ? nullptr : &symbols;
    o.label_targets = args.source && !args.no_symbols;  // source a person reads: JNZ L0802, END START
    std::string error;
    if (!args.from.empty() && !(o.from = parse_address(args.from, symbols, error))) return fail("--from: " + error, 2);
    if (!args.to.empty() && !(o.to = parse_address(args.to, symbols, error))) return fail("--to: " + error, 2);
    if (o.from && o.to && *o.from > *o.to)
        return fail(fmt::format("--from {:04X}H is above --to {:04X}H", *o.from, *o.to), 2);

    const DisasmResult r = disassemble_image(segments, o);
    if (r.bytes == 0) return fail(fmt::format("{}: no bytes in the range asked for", origin), 1);
    const std::string text = args.source ? format_source(r, o, origin) : format_listing(r);
    if (!args.output.empty()) {
        write_atomic(args.output, text);  // throws when it cannot: on_run reports it (status 1)
        return 0;
    }
    std::cout << text << std::flush;
    return std::cout ? 0 : 1;  // a closed pipe or a full disk
}

}  // namespace

void add_disasm_command(CLI::App& app, int& status) {
    Subcommand<DisasmArgs> cmd(app, "disasm", "Disassemble a program image (.hex, .bin, .com, .asm) or the monitor ROM");
    cmd->add_option("image", cmd.args->image, "The image: .hex, .bin/.rom (with --org), .com (at 0100H) or .asm")
        ->type_name("FILE");
    cmd->add_flag("--monitor", cmd.args->monitor, "Disassemble the built-in monitor ROM, with its symbols");
    cmd->add_option("--org", cmd.args->org, "Load address of a .bin/.rom/.com image");
    cmd->add_option("--from", cmd.args->from, "First address to decode (decoding starts exactly there)");
    cmd->add_option("--to", cmd.args->to, "Last address to decode");
    cmd->add_option("--map", cmd.args->maps, "asm85 JSON map(s) with symbols (asm85 --map)");
    cmd->add_flag("--no-symbols", cmd.args->no_symbols, "Print every address as a number");
    add_cpu_option(cmd.cmd, cmd.args->cpu, "Decode as this processor");
    cmd->add_flag("--source", cmd.args->source, "Write asm85 source that assembles back to the same bytes");
    cmd.output("-o,--output", cmd.args->output, "Write to this file instead of standard output");
    cmd->footer(
        "Addresses: 0800H, 0x800, 2048 or a symbol. Decoding is linear: data tables show as instructions.\n"
        "Examples:\n"
        "  alp85 disasm --monitor --from AUS --to 05C8H\n"
        "  alp85 disasm prog.hex --map prog.json\n"
        "  alp85 disasm rom.bin --org 0 --source -o rom.asm\n"
        "Exit status: 0 success, 1 an image or map that cannot be read, no bytes in the range, or an\n"
        "output that cannot be written, 2 a usage error (a bad address, range or option, an output that\n"
        "is the image or a map).");
    cmd.run(status, run_disasm);
}

}  // namespace alp85::cli
