#pragma once
/// \file
/// Every tolerance of the engine, in one place, each with why it is what it is. Where two
/// must agree (a filter must never drop what the test after it keeps), one is written in
/// terms of the other.

namespace workbook::tolerances {

/// Relative room for rounding in the tests that decide whether a pair is worth a closer
/// look (broad phase, the swept test's may-touch filter, event timing's candidates). Each
/// such test compares a few sums and products of doubles, off by a few ulps (~1e-15): 1e-9
/// is a million times that, and still far too little to let in a pair that is really apart
/// by any visible distance. Being conservative is what keeps the shortcuts exact: a pair the
/// filter keeps and the narrow phase drops costs a test; a pair it dropped would change the
/// result.
inline constexpr double conservative_slack = 1e-9;

/// The swept test's own filter (spheres_may_touch) must let through every pair the broad
/// phase's grid lists as "may touch", and both must keep every pair the swept test would
/// trace: the same slack.
inline constexpr double may_touch_slack = conservative_slack;

/// Absolute room, as a share of the coordinates in play, for the travels the grid compares:
/// travels are lengths of differences of coordinates, a few ulps of them (~1e-15) with a
/// thousandfold to spare.
inline constexpr double travel_slack = 1e-12;

/// How much wider than the largest reach a grid cell is made, so that two bodies that may
/// pair never sit two cells apart through rounding of the cell index.
inline constexpr double grid_cell_margin = 1e-6;

/// Event timing: gaps within this share of the scene's length scale count as touching. After
/// advancing exactly to a time of impact, rounding leaves a gap of a few ulps of the positions
/// (~1e-15 relative); 1e-12 holds that with room, and is still far below any gap a scene
/// could mean (a micrometre at a kilometre).
inline constexpr double touching = 1e-12;

/// Box detection: near-duplicate contact points and ties between faces, relative to the
/// boxes' size. Points 1e-9 of a box apart are one point to any responder.
inline constexpr double geometric_tie = conservative_slack;

/// Box detection: how far in front of the face below a corner of a face resting on it may lie
/// and still touch it (as a point of depth 0), relative to the boxes' size. A box resting on a
/// box keeps the depth it started with (none, for a stack built touching), so its corners sit
/// on the face below to within rounding; the contact solver stops its passes at a tolerance
/// (1e-9 m/s), and what it leaves turns a resting face by about 1e-8 rad a second (measured on
/// chapter 5's stack of ten boxes with sleeping off): some 6e-7 rad in a minute, a tenth of
/// a micrometre at the corner of a 20 cm box. 1e-5 of the box, a micrometre at 10 cm, holds
/// that with room and is far below any gap a scene could mean.
inline constexpr double resting_corner = 1e-5;

/// Box detection: edges this close to parallel (sine of the angle) have no edge-edge axis;
/// the cross product's direction there is lost to rounding, about eps / length, so 1e-6
/// keeps a wrongly tilted axis below 1e-10 of the box size.
inline constexpr double parallel_edges = 1e-6;

/// Scene files: how far a quaternion may stray from unit length. A hand-typed quaternion with
/// six or more correct digits is accepted (and normalised), a wrong one refused.
inline constexpr double quaternion_length = 1e-6;

}  // namespace workbook::tolerances
