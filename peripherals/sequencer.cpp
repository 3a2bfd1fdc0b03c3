// The stepping-motor sequencer (thesis Figure 3.10); see sequencer.h.
#include "peripherals/sequencer.h"

namespace alp85::periph {

int Sequencer::set_inputs(State& s, bool pulse, bool direction) const {
    const bool edge = p_.active_edge == Edge::Rising ? (!s.pulse && pulse) : (s.pulse && !pulse);
    s.pulse = pulse;
    s.direction = direction;
    if (!edge) return 0;
    const int dir = (direction == p_.direction_high_is_positive) ? 1 : -1;
    s.count += dir;
    return dir;
}

}  // namespace alp85::periph
