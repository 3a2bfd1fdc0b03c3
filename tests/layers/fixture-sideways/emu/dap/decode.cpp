// A front end decoding instructions itself instead of asking the debugger (issue 22): refused.
#include "asm/disasm.h"
