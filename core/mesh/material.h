#pragma once
// Material of the mass-spring tissue model (Teschner et al. 2004, the paper's ref. [19]).
//
// Unit system used throughout Resect Studio: lengths in millimetres, masses in grams,
// time in seconds. Defaults: soft tissue about as dense as water, and a stiffness constant
// (the k of Eq. 4) of 1e6 mm^2/s^2, i.e. an elastic wave speed of about 1 m/s.

namespace resect {

struct Material {
    double density = 1e-3;   ///< g/mm^3 (the k of Eq. 3)
    double stiffness = 1e6;  ///< mm^2/s^2 (the k of Eq. 4)
    double damping = 0.0;    ///< 1/s, mass-proportional velocity damping
};

} // namespace resect
