// The shared library pressing keys on the Machine: refused.
#include "emu/board/key_press.h"
