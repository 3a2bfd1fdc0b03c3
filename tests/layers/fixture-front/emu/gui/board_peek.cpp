// A window that reads the board itself instead of through the Session: refused.
#include "emu/board/machine.h"
#include "emu/script/session.h"
