// The breakpoints a client has set, of every DAP kind, as the adapter keeps them between
// requests: source lines (bound through the line map), functions (symbols), instructions
// (addresses) and data (memory). The machine's own breakpoints and watchpoints are armed from
// this table (Adapter::arm).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace alp85::dap {

struct Breakpoint {
    int id = 0;
    bool verified = false;
    std::string message;             // why not verified, or where it moved
    int line = 0;                    // source: the line asked for
    std::optional<int> bound_line;   // source: the line with code it binds to
    std::string name;                // function: the symbol; instruction: the reference
    std::vector<std::uint16_t> addresses;
    std::string condition, hit_condition, log_message;
    std::uint64_t hits = 0;
};

struct DataBreakpoint {
    int id = 0;
    std::string data_id;          // "1B32H:2": address and length, what dataBreakpointInfo gave
    std::uint16_t address = 0;
    std::uint16_t length = 1;
    std::string access = "readWrite";  // DAP's: read, write (with a new value), readWrite
    std::string what;                  // "YAC (1B32H)", for the Debugger's messages
    std::string condition, hit_condition;
    std::uint64_t hits = 0;
    bool verified = false;
    std::string message;
};

struct BreakpointTable {
    std::map<std::string, std::vector<Breakpoint>> source;  // by the client's path
    std::vector<Breakpoint> function, instruction;
    std::vector<DataBreakpoint> data;
    int next_id = 1;

    // Every code breakpoint that covers `pc`.
    std::vector<Breakpoint*> at(std::uint16_t pc);
};


// "1B32H:2" <-> address and length (dataBreakpointInfo's dataId).
std::string data_id(std::uint16_t address, std::uint16_t length);
std::optional<std::pair<std::uint16_t, std::uint16_t>> parse_data_id(const std::string& id);

}  // namespace alp85::dap
