// The incremental linear transducer and its direction discriminator; see transducer.h.
#include "peripherals/transducer.h"

#include <cmath>

namespace alp85::periph {

Transducer::Transducer(Params p) : p_(p), quads_per_mm_(4.0 / p.pitch_mm) {}

void Transducer::init(State& s, double x_mm) const {
    s.q = q_of(x_mm);
    s.count = 0;
    s.positive = true;
}

void Transducer::walk(State& s, std::int64_t q) const {
    // One quadrature state at a time, as the logic sees the photocells change.
    while (s.q < q) {
        ++s.q;
        s.positive = true;
        if ((s.q & 3) == 0) ++s.count;  // crossed a line (state 3 -> 0)
    }
    while (s.q > q) {
        if ((s.q & 3) == 0) --s.count;  // crossing a line backwards (state 0 -> 3)
        --s.q;
        s.positive = false;
    }
}

}  // namespace alp85::periph
