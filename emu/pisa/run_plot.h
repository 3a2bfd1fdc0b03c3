// A run's toolpath as a chart (emu/plot): the exact path of the tape's elements (dashed), the 6 ms
// outputs and the tables under their servos, in mm from program zero. `alp85 pisa --plot` and the
// docs' figures draw the same chart.
#pragma once

#include <string>

#include "emu/pisa/run.h"
#include "emu/plot/plot.h"

namespace alp85::pisa {

plot::Chart toolpath_chart(const std::string& title, const Tape& tape, const RunResult& r);

}  // namespace alp85::pisa
