#include "emu/program/firmware.h"

#ifdef ALP85_HAVE_MONITOR
#include <stdexcept>

#include "emu/program/symbols.h"
#include "monitor_embed.h"

namespace alp85 {
extern const char kMonitorMap[];  // monitor.json, embedded by emu/embed_text.cmake
}
#endif

namespace alp85::firmware {

#ifdef ALP85_HAVE_MONITOR
bool have_monitor() { return true; }
Firmware monitor() {
    Firmware f;
    f.segments.push_back({kMonitorRom_origin, {kMonitorRom, kMonitorRom + kMonitorRom_size}});
    if (const std::string err = f.symbols.load_map_text(kMonitorMap); !err.empty())
        throw std::logic_error("the built-in monitor map is damaged: " + err);
    return f;
}
const char* monitor_map() { return kMonitorMap; }
#else
bool have_monitor() { return false; }
Firmware monitor() { return {}; }
const char* monitor_map() { return ""; }
#endif

}  // namespace alp85::firmware
