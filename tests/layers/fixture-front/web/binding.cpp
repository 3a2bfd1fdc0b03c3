// The page decoding the display itself: refused.
#include "emu/front/views.h"
#include "peripherals/seven_segment.h"
