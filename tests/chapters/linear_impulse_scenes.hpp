#pragma once
// Runs chapter 3's scenes and measures what its page says about them, for the scene checks
// and the page's number lookups alike.
#include <string>
#include <vector>

#include "workbook/probes.hpp"
#include "workbook/rigid_body.hpp"

namespace workbook::chapter3 {

/// A scene run to its end.
struct Run {
    std::vector<RigidBody> bodies;  ///< the bodies after the last step
    Probes last;                    ///< the probes after the last step
    int responses = 0;              ///< steps in which a response changed the kinetic energy or a contact existed
};

/// Runs `relative_path` (from the source folder) with the reference responders.
Run run_scene(const std::string& relative_path);

/// The same, with the position correction's slop set to `slop` (a large slop turns it off).
Run run_scene_with_slop(const std::string& relative_path, double slop);

struct CartsCase {
    std::string file;
    double e;
};
/// The four head-on cart scenes, e = 0, 0.5, 0.8, 1.
std::vector<CartsCase> carts_cases();

struct BounceReport {
    std::vector<double> apexes;  ///< height of the ball's lowest point at each apex after a bounce, m
};
BounceReport bouncing_ball_report();

struct CradleOrders {
    std::vector<double> forward_after_one_step;  ///< pressed row, contacts in index order, one respond pass
    std::vector<double> reverse_after_one_step;  ///< pressed row, contacts in reverse order, one pass
    int reverse_steps_to_finish = 0;             ///< passes until the last ball moves
    std::vector<double> reverse_final;           ///< the velocities then
    std::vector<double> simultaneous;            ///< all four contacts solved at once
};
CradleOrders cradle_orders();

struct StackReport {
    double fall = 0.0;          ///< how far the small ball fell before it was hit, m
    double rise = 0.0;          ///< how far it rose after, m
    double factor = 0.0;        ///< rise / fall
    double ideal_factor = 0.0;  ///< ((3M - m)/(M + m))^2
};
StackReport stacked_balls_report();

}  // namespace workbook::chapter3
