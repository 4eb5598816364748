#pragma once
/// \file
/// Scene families with a closed form, and how far a run lands from it.
///
/// Every family builds its world for the given WorldSettings (time step, integrator, contact
/// timing) and model, runs it, and returns one error number, relative and dimensionless, so
/// that the families can share the bench's axes:
///  - bouncing ball: the largest relative error of the apex after bounce k against e^(2k) h0,
///    over the first `bounces` bounces (and, beside it, of the bounce times, s);
///  - head-on pair:  the largest velocity error over |v1 - v2| and position error over r1 + r2,
///    at the end, against the closed-form impulse and the exact time of impact;
///  - cradle:        the same for a ball that hits a row of four touching balls (cradle_error());
///  - stacked drop:  the relative error of the small ball's apex after a big ball carrying it
///    bounces off the ground.
/// A run that never reaches what is measured (a bounce is missed) has error 1.

#include <string>
#include <vector>

#include "workbook/response_model.hpp"
#include "workbook/world.hpp"

namespace workbook::accuracy {

/// One bounce as observed from the state after the step that contained it.
struct Bounce {
    double time = 0.0;  ///< s, when the ball touched the ground (inferred from the state)
    double apex = 0.0;  ///< m, the height of the ball's bottom at the next apex (from y and v_y)
};

/// A ball dropped from rest, its bottom h0 above a ground plane at y = 0.
struct BouncingBall {
    double h0 = 1.0;          ///< m
    double radius = 0.1;      ///< m
    double restitution = 0.8;
    double g = 9.81;          ///< m/s^2
    /// Closed form: the k-th bounce (k >= 1) happens at sqrt(2 h0 / g) (1 + 2 sum_{j<k} e^j).
    [[nodiscard]] double bounce_time(int k) const;
    /// Closed form: the apex after bounce k is e^(2k) h0.
    [[nodiscard]] double apex(int k) const;
    /// The world: ball (index 0) and ground (index 1).
    [[nodiscard]] World world(WorldSettings settings, const ResponseModel& model) const;
};

/// Steps `world` (a BouncingBall world) until `count` bounces are seen or `max_time` passes.
/// A bounce is a step after which v_y > 0 where it was <= 0 before; from the state (y, v_y) at
/// the end of that step and free flight, the touch time is t - tau with
/// tau = (sqrt(v_y^2 + 2 g (y - r)) - v_y) / g, and the apex is y - r + v_y^2 / (2 g).
std::vector<Bounce> observe_bounces(World& world, const BouncingBall& ball, int count, double max_time);

/// The result of one family run.
struct FamilyError {
    double error = 1.0;        ///< the family's relative error (see the file comment)
    double time_error = 0.0;   ///< bouncing ball only: the largest bounce-time error, s
    std::size_t steps = 0;     ///< world steps taken
};

FamilyError bouncing_ball_error(const WorldSettings& settings, const ResponseModel& model, int bounces = 10);
FamilyError head_on_error(const WorldSettings& settings, const ResponseModel& model);
/// Five touching balls at rest; a sixth, 0.05 m away at 1 m/s, hits the row (e = 1, no gravity).
/// Closed form: the moving ball stops and the last ball leaves at 1 m/s, everyone else at rest.
FamilyError cradle_error(const WorldSettings& settings, const ResponseModel& model);
FamilyError stacked_drop_error(const WorldSettings& settings, const ResponseModel& model);

/// A family for the bench: its id (file names), a title (figures) and its run.
struct Family {
    std::string id;
    std::string title;
    FamilyError (*run)(const WorldSettings&, const ResponseModel&);
    bool gravity = true;  ///< whether settings.gravity should be set (the family sets its own value)
};

/// Every family with a closed form so far. Chapter 2 and 4 families (tilted rod, torque-free box)
/// join when those chapters exist.
std::vector<Family> families();

}  // namespace workbook::accuracy
