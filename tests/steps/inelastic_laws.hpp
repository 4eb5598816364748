#pragma once
// The laws chapter 1's steps are checked against, shared by the public step tests and the
// hidden tests so that a student reads the same law, statement and hint from both.
#include "feedback.hpp"

namespace workbook::inelastic_laws {

using workbook::testing::Law;

inline const Law momentum{"conservation of linear momentum", "m1 v1 + m2 v2 must be the same before and after, to rounding",
                          "weight each velocity by its mass: (m1 v1 + m2 v2) / (m1 + m2); with inverse masses w = 1/m "
                          "that is (w2 v1 + w1 v2) / (w1 + w2), which stays exact even when one mass is a million "
                          "times the other"};
inline const Law stick{"perfectly inelastic bodies stick together", "after the collision v1' = v2', in every component",
                       "assign the common velocity to body1.velocity AND body2.velocity, the whole vector"};
inline const Law immovable{"an immovable body (inverse mass 0) has infinite mass",
                           "it keeps its velocity exactly, the other body takes that velocity, and nothing becomes NaN",
                           "write the common velocity with inverse masses; when one is 0 return that body's velocity, "
                           "and with two immovable bodies change nothing rather than divide by w1 + w2 = 0"};
inline const Law separating{"only approaching bodies collide", "when dot(v1 - v2, n) >= 0 the velocities stay exactly as they are",
                            "compute dot(body1.velocity - body2.velocity, contact.normal) first and return when it is >= 0"};
inline const Law approach{"an approaching pair must be resolved", "after resolve, dot(v1' - v2', n) >= 0: the pair no longer approaches",
                          "leave a pair alone only when dot(v1 - v2, n) >= 0; when it is < 0 the bodies must still merge"};
inline const Law energy{"energy lost in a perfectly inelastic collision", "Delta E = 1/2 mu |v1 - v2|^2, mu = m1 m2 / (m1 + m2)",
                        "mu = 1 / (w1 + w2) with inverse masses (the other body's mass against an immovable one, and "
                        "nothing lost between two); square the length of the whole relative velocity"};

// A wrong early return (step 4's test of dot(v1 - v2, n), say reversed) leaves an approaching
// pair untouched, and steps 2 and 3 fail with it. Their usual hints would then send the
// student to the assignment or the inverse masses, which may well be right; these hints say
// what resolve did and what their own law needs of it.
inline const Law stick_untouched{stick.name, stick.statement,
                                 "resolve left both velocities as they were, yet this pair approaches (dot(v1 - v2, n) < 0) "
                                 "and must leave together: check that resolve reaches the merge for an approaching pair "
                                 "(the condition of any early return), then give both bodies the common velocity"};
inline const Law immovable_untouched{immovable.name, immovable.statement,
                                     "resolve left both velocities as they were, yet the movable body approaches the "
                                     "immovable one and must take its velocity: check that resolve reaches the merge for "
                                     "an approaching pair (the condition of any early return)"};

/// True when resolve changed neither velocity, to the bit.
inline bool untouched(const RigidBody& body1_before, const RigidBody& body2_before, const RigidBody& body1_after,
                      const RigidBody& body2_after) {
    return body1_before.velocity == body1_after.velocity && body2_before.velocity == body2_after.velocity;
}

/// Step 2's and step 3's laws, with the hint that fits what resolve did to an approaching pair.
inline const Law& stick_after(bool resolve_changed_nothing) { return resolve_changed_nothing ? stick_untouched : stick; }
inline const Law& immovable_after(bool resolve_changed_nothing) {
    return resolve_changed_nothing ? immovable_untouched : immovable;
}

}  // namespace workbook::inelastic_laws
