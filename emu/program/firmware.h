// Firmware built into alp85 by the build: the ALP 85 monitor EPROM (firmware/monitor), the
// two builds of the thesis firmware (firmware/thesis: "thesis" as printed, "thesis-fixed") and the
// master program for the expansion EPROM (firmware/master).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "emu/core/image.h"
#include "emu/program/symbols.h"

namespace alp85::firmware {

// A built-in firmware image and the symbols of its source (from asm85's map).
struct Firmware {
    std::string name;
    std::vector<ImageSegment> segments;
    SymbolTable symbols;  // its symbols and source lines (from asm85's map)
    bool expansion_eprom = false;  // it lives in the expansion EPROM: loading it fits that option
};

bool have_monitor();
// The 2 KB monitor EPROM image at 0000H and its symbols (AUS, UMW, SAVEPC, ...); empty when this
// build has no monitor.
Firmware monitor();
// The monitor's asm85 map (JSON, "alp85-asm-map"); empty when this build has no monitor.
const char* monitor_map();

// Every firmware built into this alp85, by name ("monitor", "thesis", "thesis-fixed", "master"), with a
// line saying what it is.
struct Entry {
    std::string_view name;
    std::string_view what;
};
std::vector<Entry> builtin();
// The named firmware (image and symbols), or nullopt.
std::optional<Firmware> find(std::string_view name);

// ALP85's data folder: the firmware sources, images and maps, and the examples (cmake --install,
// docs/install.md). Installed, it is <prefix>/share/alp85, found from the running executable
// (<prefix>/bin/alp85); run from a build folder, it is the source tree it was built from. Empty
// when neither exists.
std::filesystem::path data_dir();
// Where a source file named by a built-in map (a path in the source tree alp85 was built from)
// is read: the same file under data_dir(), the installed copy for an installed alp85 (whether or
// not that source tree is still there); else the path unchanged.
std::string locate_source(const std::string& path);

}  // namespace alp85::firmware
