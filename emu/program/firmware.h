// Firmware built into alp85 by the build: the ALP 85 monitor EPROM (firmware/monitor).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "emu/core/image.h"
#include "emu/program/symbols.h"

namespace alp85::firmware {

// A built-in firmware image and the symbols of its source (from asm85's map).
struct Firmware {
    std::vector<ImageSegment> segments;
    SymbolTable symbols;  // its symbols and source lines (from asm85's map)
};

bool have_monitor();
// The 2 KB monitor EPROM image at 0000H and its symbols (AUS, UMW, SAVEPC, ...); empty when this
// build has no monitor.
Firmware monitor();
// The monitor's asm85 map (JSON, "alp85-asm-map"); empty when this build has no monitor.
const char* monitor_map();

}  // namespace alp85::firmware
