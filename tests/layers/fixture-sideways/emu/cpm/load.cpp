// The CP/M machine pulling in the program layer beyond its Intel HEX reader: refused.
#include "emu/program/image_loader.h"
