// The CPU description the front ends read, alone in its file: a program may link its own in its
// place (tests/debug/toy_register.cpp adds a register to the 8085's in one line and shows that
// every front end renders it).
#include "emu/core/cpu_registers.h"

namespace alp85::cpu {

const Description& description() {
    static const Description d = i8085_description();
    return d;
}

}  // namespace alp85::cpu
