#pragma once
// The laws chapter 2's steps are checked against, shared by the public step tests and the
// hidden tests so that a student reads the same law, statement and hint from both.
#include "feedback.hpp"

namespace workbook::projection_laws {

using workbook::testing::Law;

inline const Law split{"projection splits the depth by inverse mass along the normal",
                       "body 1 moves +d w1/(w1+w2) n and body 2 moves -d w2/(w1+w2) n, d the deepest penetration",
                       "n points from body 2 to body 1, so body 1 goes along +n and body 2 along -n; the two shares "
                       "add up to the whole depth, and the lighter body (larger w) takes the larger share"};
inline const Law centre_of_mass{"the centre of mass of the pair does not move",
                                "m1 dx1 + m2 dx2 = 0: projection is an internal push between the two bodies",
                                "share the depth in proportion to the inverse masses, w1/(w1+w2) and w2/(w1+w2), "
                                "not half each and not in proportion to the masses themselves"};
inline const Law immovable{"an immovable body (inverse mass 0) never moves",
                           "its position stays exactly where it was, the other body takes the whole push, two "
                           "immovable bodies stay put, and nothing becomes NaN",
                           "with inverse masses the immovable body's share w/(w1+w2) is exactly 0 and the other's is "
                           "1; only two immovable bodies (w1 + w2 = 0) need leaving alone before any division"};
inline const Law positions_only{"projection changes positions, never velocities",
                                "every velocity and angular velocity is exactly what it was, so momentum and kinetic "
                                "energy are unchanged",
                                "a position correction is not an impulse: it moves the bodies out of each other and "
                                "nothing else; stopping or bouncing them is the velocity stage's job"};
inline const Law still_pushed{"an overlapping pair must still be pushed apart",
                              "while velocities are kept, the separation along n grows by at least the depth",
                              "keep the push of step 1 and leave only the velocities alone"};
inline const Law no_overlap{"bodies that only touch are not pushed",
                            "a contact of depth 0 moves nothing",
                            "the push is proportional to the depth, so zero depth must give zero displacement, not a "
                            "fixed nudge"};
inline const Law knobs{"a fraction of the depth beyond the slop is removed per pass",
                       "one pass removes beta max(d - s, 0): nothing within the slop, never a pull",
                       "subtract the slop once, clamp at zero so a shallow contact is left alone rather than pulled "
                       "together, then take the fraction beta of what is left"};
inline const Law decay{"the depth beyond the slop decays geometrically",
                       "after k passes the depth is s + (d0 - s)(1 - beta)^k",
                       "each pass removes the fraction beta of the depth beyond the slop that is left, so (1 - beta) "
                       "of it remains; remove it from the depth measured now, not from the first depth"};

}  // namespace workbook::projection_laws
