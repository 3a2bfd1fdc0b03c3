#include "emu/dap/launch.h"

#include <fmt/format.h>

#include "emu/program/firmware.h"
#include "emu/script/parser.h"
#include "emu/util/input_file.h"
#include "emu/util/text.h"

namespace alp85::dap {
namespace {

std::uint64_t time_arg(const Json& args, std::string_view key, std::uint64_t fallback) {
    const auto text = opt_string(args, key);
    if (!text) return fallback;
    const auto t = script::parse_time(*text);
    if (!t) throw RequestError(fmt::format("argument '{}': bad time '{}' (a number with a unit: t, us, ms or s)", key, *text));
    return *t;
}

}  // namespace

LaunchConfig parse_launch(const Json& args) {
    if (!args.is_object()) throw RequestError("launch needs its arguments (an object)");
    LaunchConfig c;
    c.cwd = opt_string(args, "cwd").value_or(std::filesystem::current_path().string());
    c.program = opt_string(args, "program").value_or("");
    c.map = opt_string(args, "map").value_or("");
    c.firmware = opt_string(args, "firmware").value_or("");
    // One way to name firmware, as on alp85's command lines: a built-in name given as the program
    // is that firmware, a file given as the firmware is the program.
    const auto file = [&](const std::string& p) {
        std::error_code ec;
        return std::filesystem::is_regular_file(std::filesystem::path(c.cwd) / p, ec);
    };
    if (c.firmware.empty() && !c.program.empty() && firmware::find(c.program) && !file(c.program)) std::swap(c.firmware, c.program);
    else if (c.program.empty() && !c.firmware.empty() && !firmware::find(c.firmware) && file(c.firmware)) std::swap(c.firmware, c.program);
    c.rom = opt_string(args, "rom").value_or("");
    if (c.program.empty() && c.firmware.empty() && c.rom.empty())
        throw RequestError("launch needs 'program' (a .asm or .hex file), 'firmware' (one built in, e.g. thesis-fixed) "
                           "or, on a board whose ROM is yours, 'rom'");
    for (const auto& [name, value] : opt_object(args, "defines").items()) {
        if (value.is_number_integer()) c.defines.emplace_back(name, std::to_string(value.get<std::int64_t>()));
        else if (value.is_string()) c.defines.emplace_back(name, value.get<std::string>());
        else throw RequestError(fmt::format("defines: '{}' must be a number or a string", name));
    }
    c.board = opt_string(args, "board").value_or(std::string(script::Session::default_board().name));
    if (!script::Session::find_board(c.board))
        throw RequestError(fmt::format("argument 'board': no board '{}' ({})", c.board, script::Session::board_names()));
    const bool builtin = script::Session::find_board(c.board)->builtin_firmware;  // the ALP 85's monitor and firmware
    c.monitor = opt_bool(args, "monitor").value_or(builtin);
    if (!c.rom.empty() && builtin)
        throw RequestError("argument 'rom' is for \"board\": \"sdk85\" (the ALP 85's monitor is built in; a program "
                           "of yours goes in 'program')");
    if (!c.rom.empty() && c.monitor) throw RequestError("argument 'rom' replaces the monitor: not with \"monitor\": true");
    const std::string motor = opt_string(args, "motor").value_or("physical");
    if (motor != "ideal" && motor != "physical") throw RequestError("argument 'motor' must be \"ideal\" or \"physical\"");
    c.motor = motor == "ideal" ? periph::MachineTool::MotorModel::Ideal : periph::MachineTool::MotorModel::Physical;
    c.keys = opt_string(args, "keys").value_or("");
    if (!c.keys.empty()) {
        std::string why;
        std::size_t at = 0;
        if (!script::parse_key_list(c.keys, why, at)) throw RequestError(fmt::format("argument 'keys': {} at column {}", why, at + 1));
    }
    c.boot = time_arg(args, "bootTime", board::tstates_from_ms(500));
    c.script = opt_string(args, "script").value_or("");
    c.stop_on_entry = opt_bool(args, "stopOnEntry").value_or(false);
    c.real_time = opt_bool(args, "realTime").value_or(true);
    c.stop_on_runaway = opt_bool(args, "stopOnRunaway").value_or(true);
    return c;
}

void load_program(const LaunchConfig& config, script::Session& session, ProgramMap& map,
                  std::vector<std::string>& warnings) {
    script::Session::Boot boot;
    boot.motor = config.motor;
    boot.monitor = config.monitor;
    if (!config.rom.empty()) {
        std::filesystem::path rom = config.rom;
        if (rom.is_relative()) rom = config.cwd / rom;
        session.add_input(rom, "the board's ROM");  // the REPL's save, record, plot must not replace it
        boot.rom = std::filesystem::absolute(rom);
    }
    boot.pc_at_program = !config.monitor;
    if (config.monitor && !firmware::have_monitor())
        throw RequestError("this alp85 was built without the monitor ROM (set \"monitor\": false)");
    map = {};
    if (!config.firmware.empty()) {
        if (!firmware::find(config.firmware)) {
            std::string names;
            for (const auto& e : firmware::builtin()) names += (names.empty() ? "" : ", ") + std::string(e.name);
            throw RequestError(fmt::format("no firmware '{}' in this alp85 (built in: {})", config.firmware, names));
        }
        boot.firmware.push_back(config.firmware);
    }
    if (!config.program.empty()) {
        std::filesystem::path path = config.program;
        if (path.is_relative()) path = config.cwd / path;
        map.program_path = path.string();
        if (const std::string why = program_file_problem(path); !why.empty()) throw RequestError(why);
        session.add_input(path, "the launched program");  // the REPL's save, record, plot must not replace it
        boot.images.push_back({std::filesystem::absolute(path), std::nullopt});  // not again from the session's cwd
        boot.defines = config.defines;
        if (!config.map.empty()) {
            std::filesystem::path mp = config.map;
            if (mp.is_relative()) mp = config.cwd / mp;
            session.add_input(mp, "the launched program's map");
            boot.maps.push_back(std::filesystem::absolute(mp));
        }
    }
    if (!config.keys.empty()) {
        std::string why;
        std::size_t at = 0;
        boot.keys = script::parse_key_list(config.keys, why, at).value_or(std::vector<script::KeyRef>{});
        boot.boot_time = config.boot;
    }
    script::Session::BootReport report;
    const script::Session::Outcome o = session.boot(boot, &report);
    warnings.insert(warnings.end(), report.warnings.begin(), report.warnings.end());
    if (o.status != script::Session::Status::Ok) throw RequestError(o.message);
    map.code = report.code;
}

}  // namespace alp85::dap
