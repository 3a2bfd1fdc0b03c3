#include "emu/firmware.h"

#ifdef ALP85_HAVE_MONITOR
#include "monitor_embed.h"
#endif

namespace alp85::firmware {

#ifdef ALP85_HAVE_MONITOR
bool have_monitor() { return true; }
std::vector<ImageSegment> monitor_rom() {
    return {ImageSegment{kMonitorRom_origin, {kMonitorRom, kMonitorRom + kMonitorRom_size}}};
}
#else
bool have_monitor() { return false; }
std::vector<ImageSegment> monitor_rom() { return {}; }
#endif

}  // namespace alp85::firmware
