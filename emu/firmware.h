// Firmware built into alp85 by the build: the ALP 85 monitor EPROM (firmware/monitor).
#pragma once

#include <vector>

#include "emu/machine.h"

namespace alp85::firmware {

bool have_monitor();
// The 2 KB monitor EPROM image at 0000H (empty when this build has no monitor).
std::vector<ImageSegment> monitor_rom();

}  // namespace alp85::firmware
