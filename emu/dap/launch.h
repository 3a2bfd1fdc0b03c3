// What `launch` asks for (docs/editors.md lists the attributes), and what was loaded where: the
// firmware assembled on the fly with its line map, the monitor, the motor model, the keys typed
// after the boot.
#pragma once

#include <bitset>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "emu/dap/protocol.h"
#include "emu/script/session.h"

namespace alp85::dap {

struct LaunchConfig {
    std::filesystem::path cwd;      // relative paths start here
    std::string program;            // .asm (assembled now, map kept) or .hex
    std::string map;                // for a .hex: asm85's map (symbols and lines)
    std::string firmware;           // a built-in one ("thesis-fixed"), instead of or beside program
    std::vector<std::pair<std::string, std::string>> defines;  // for a .asm: NAME=VALUE
    bool monitor = true;            // the monitor EPROM at 0000H; without it the program starts at
                                    // its END address (or its first byte)
    periph::MachineTool::MotorModel motor = periph::MachineTool::MotorModel::Physical;
    std::string board = "alp85";    // the board to build (alp85, sdk85); another than the ALP 85 has no built-in monitor
    std::string rom;                // that board's ROM from the user's file (.bin, .hex, .asm), as alp85 run --rom
    std::string keys;               // typed after the boot ("R 7 0800 EXEC 0012")
    std::uint64_t boot = 0;         // T-states from RESET to the first key (default 500 ms)
    std::string script;             // a command-language file run before the start
    bool stop_on_entry = false;
    bool real_time = true;          // runs paced to the board's clock; false: as fast as the host
    bool stop_on_runaway = true;    // an instruction fetched where nothing was loaded stops the run
};

// The launch arguments, checked; a RequestError says which is wrong.
LaunchConfig parse_launch(const Json& args);

// Where the CPU may fetch instructions: the bytes loaded at launch and the RAM (the monitor's GO
// trampoline at 20C1H, programs typed in). A fetch anywhere else - unprogrammed EPROM, nothing
// mapped - is a runaway.
struct ProgramMap {
    std::bitset<0x10000> code;
    std::string program_path;  // the program as resolved, for messages
};

// Loads what `config` names into the session's machine and its debugger's symbol table, resets
// the board and schedules the keys. Warnings (asm85's, file:line:col) are appended to `warnings`.
// Throws RequestError with every assembler error as file:line:col.
void load_program(const LaunchConfig& config, script::Session& session, ProgramMap& map,
                  std::vector<std::string>& warnings);

}  // namespace alp85::dap
