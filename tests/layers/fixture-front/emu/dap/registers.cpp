// DAP naming the CPU's register file itself: refused.
#include "emu/core/i8085.h"
