#pragma once
// Placeholder laws of chapter 6 (the chapter's graded side replaces this file).
#include "feedback.hpp"

namespace workbook::friction_laws {

using workbook::testing::Law;

inline const Law mixed{"a pair's coefficient is the geometric mean", "mu = sqrt(mu1 mu2)",
                       "multiply the two coefficients and take the square root"};
inline const Law frame{"the tangents and the normal make a right-handed orthonormal frame",
                       "t1 . n = t2 . n = t1 . t2 = 0, |t1| = |t2| = 1, t1 x t2 = n, for every unit normal",
                       "cross the normal with the world axis it is least aligned with, normalise, then t2 = n x t1"};
inline const Law tangent_mass{"the tangential effective mass has the angular terms",
                              "m_t = 1 / (1/m1 + 1/m2 + t . ((I1^-1 (r1 x t)) x r1 + (I2^-1 (r2 x t)) x r2)); a ball "
                              "on the ground has 2/7 m",
                              "chapter 5's effective mass with the tangent for the normal"};
inline const Law cone{"the friction impulse stays within the cone",
                      "the accumulated pair is kept while |J_t| <= mu_s J_n, else scaled to mu_d J_n",
                      "add the increment, compare the sum's length with mu_s J_n, scale to mu_d J_n when beyond"};
inline const Law pass{"friction stops the slip when the cone allows it",
                      "after the pass the slip at a sticking point is 0; friction acts only where J_n > 0",
                      "increments -m_t (s . t) through accumulate_friction, applied with the angular terms"};

}  // namespace workbook::friction_laws
