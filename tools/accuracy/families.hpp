#pragma once
/// \file
/// Scene families with a closed form, and how far a run lands from it.
///
/// Every family builds its world for the given WorldSettings (time step, integrator, contact
/// timing) and model, runs it, and returns one error number, relative and dimensionless, so
/// that the families can share the bench's axes:
///  - head-on pair:  the largest velocity error over |v1 - v2| and position error over r1 + r2,
///    at the end, against the closed-form impulse and the exact time of impact (chapter 1 with
///    e = 0, chapter 3 with e = 0.5);
///  - resting stack: the deepest any ball of a column resting on the ground sinks below its
///    resting height, over its radius (chapter 2);
///  - bouncing ball: the largest relative error of the apex after bounce k against e^(2k) h0,
///    over the first `bounces` bounces (and, beside it, of the bounce times, s);
///  - cradle:        the head-on error for a ball that hits a row of four touching balls;
///  - stacked drop:  the relative error of the small ball's apex after a big ball carrying it
///    bounces off the ground;
///  - tilted rod:    the velocity errors of a box that lands on one edge, against the impulse
///    with the angular term (chapter 4, rigid_families.cpp);
///  - torque-free box: the largest relative drift of the angular momentum L (the vector, so
///    its length and direction) and of the kinetic energy of a box spinning freely about a
///    direction near its middle axis (rigid_families.cpp);
///  - block on an incline: how far the block's slide and speed after 1 s are from the
///    closed form, over the frictionless slide, for a block that slides and one that sticks
///    (friction_families.cpp);
///  - thrown ball: the state after 1 s of a ball set sliding without spin, against the slide
///    and then the roll at 5/7 of its speed (friction_families.cpp).
/// A run that never reaches what is measured (a bounce is missed) has error 1.
///
/// The scenes' numbers and closed forms live in small structs (HeadOn, Cradle, BouncingBall)
/// so that the peer engines (peers.hpp) run the same scenes and are measured the same way.

#include <cstddef>
#include <span>
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
    /// The largest relative apex error and the largest bounce-time error (s) of `seen` against
    /// the first `count` bounces; error 1 when fewer were seen.
    [[nodiscard]] std::pair<double, double> errors(std::span<const Bounce> seen, int count) const;
};

/// Finds bounces in a ball's state read after every step: a bounce is a step after which
/// v_y > 0 where it was <= 0 before; from the state (y, v_y) at the end of that step and free
/// flight, the touch time is t - tau with tau = (sqrt(v_y^2 + 2 g (y - r)) - v_y) / g, and the
/// apex is y - r + v_y^2 / (2 g). Used for the workbook and the peers alike.
class BounceObserver {
public:
    BounceObserver(const BouncingBall& ball, double start_vy) : ball_(ball), previous_vy_(start_vy) {}
    /// The state after a step that ended at time t.
    void after_step(double t, double y, double vy);
    [[nodiscard]] const std::vector<Bounce>& bounces() const { return bounces_; }

private:
    BouncingBall ball_;
    double previous_vy_;
    std::vector<Bounce> bounces_;
};

/// Steps `world` (a BouncingBall world) until `count` bounces are seen or `max_time` passes.
std::vector<Bounce> observe_bounces(World& world, const BouncingBall& ball, int count, double max_time);

/// Two balls meeting head-on along x, no gravity: 1 kg at 2 m/s and 3 kg at -1 m/s, radius
/// 0.5 m, surfaces 0.3071 m apart, so that they touch at 0.10237 s (between steps).
struct HeadOn {
    double m1 = 1.0, m2 = 3.0, v1 = 2.0, v2 = -1.0, radius = 0.5, gap = 0.3071;
    double restitution = 0.5;
    [[nodiscard]] double x1() const { return -(2.0 * radius + gap); }
    [[nodiscard]] double x2() const { return 0.0; }
    [[nodiscard]] double time_of_impact() const { return gap / (v1 - v2); }
    /// Closed form: v1' = (p - m2 e (v1 - v2)) / (m1 + m2), v2' = (p + m1 e (v1 - v2)) / (m1 + m2).
    [[nodiscard]] double v1_after() const;
    [[nodiscard]] double v2_after() const;
    /// max(|dv| / (v1 - v2), |dx| / (2 r)) over both balls at time t.
    [[nodiscard]] double error(double t, double x1, double vx1, double x2, double vx2) const;
};

/// Newton's cradle: five touching balls at rest; a sixth, 0.0513 m away at 1 m/s, hits the row
/// (e = 1, no gravity). Closed form: the moving ball stops, the last ball leaves at 1 m/s.
struct Cradle {
    double radius = 0.1, speed = 1.0, gap = 0.0513;
    static constexpr int row = 4;  ///< balls in the row besides the incoming one
    [[nodiscard]] double start_x(int i) const;  ///< ball i = 0 (incoming) .. row
    /// The largest of |dv| / v and |dx| / r over all balls at time t.
    [[nodiscard]] double error(double t, std::span<const double> x, std::span<const double> vx) const;
};

/// The result of one family run.
struct FamilyError {
    double error = 1.0;        ///< the family's relative error (see the file comment)
    double time_error = 0.0;   ///< bouncing ball only: the largest bounce-time error, s
    std::size_t steps = 0;     ///< world steps taken
};

FamilyError bouncing_ball_error(const WorldSettings& settings, const ResponseModel& model, int bounces = 10);
FamilyError head_on_error(const WorldSettings& settings, const ResponseModel& model, const HeadOn& pair = {});
FamilyError cradle_error(const WorldSettings& settings, const ResponseModel& model);
FamilyError stacked_drop_error(const WorldSettings& settings, const ResponseModel& model);

/// A column of `balls` balls (1 kg, radius 0.1 m, e = 0) resting on the ground and on each
/// other, under gravity, for 1 s. At rest is the closed form: every ball stays at its height.
FamilyError resting_stack_error(const WorldSettings& settings, const ResponseModel& model, int balls = 3);

/// A box 1 m by 5 cm by 5 cm, 2 kg, tilted 30 degrees and not spinning, dropped so that its
/// lower edge lands at u = 3 m/s on frictionless ground, e = 0.5 (chapter 4's worked example,
/// with gravity). Its numbers and closed form:
struct TiltedRod {
    double mass = 2.0, length = 1.0, thickness = 0.05, tilt_degrees = 30.0, impact_speed = 3.0;
    double restitution = 0.5, g = 9.81;
    /// Horizontal distance from the centre to the lower edge, (L/2) cos(theta) - (t/2) sin(theta).
    [[nodiscard]] double lever() const;
    /// The moment about the axis along the edge, m (L^2 + t^2) / 12.
    [[nodiscard]] double moment() const;
    /// J = (1 + e) u / (1/m + d^2 / I); for a thin rod (t = 0), (1 + e) m u / (1 + 3 cos^2 theta).
    [[nodiscard]] double impulse() const;
    /// The centre's vertical velocity and the spin just after the impact: -u + J/m and d J / I.
    [[nodiscard]] double velocity_after() const;
    [[nodiscard]] double spin_after() const;
    /// When the edge lands, dropped from rest: u / g.
    [[nodiscard]] double time_of_impact() const { return impact_speed / g; }
    /// The world: box (index 0) and ground (index 1); the edge is u^2 / (2 g) above the ground.
    [[nodiscard]] World world(WorldSettings settings, const ResponseModel& model) const;
};
/// At the end of the step that answered the landing: max(|v_y - v_exact(t)|, |w - w'| d) / u,
/// with v_exact(t) = v' - g (t - t_hit) (free flight after the impact).
FamilyError tilted_rod_error(const WorldSettings& settings, const ResponseModel& model);

/// A free box, 0.5 by 0.25 by 0.1 m half extents, 1 kg, spinning at 4 rad/s about its middle
/// axis with a small tilt, no gravity, for 10 s (it flips over and over: the tennis racket).
/// L (world frame) and E = 1/2 w . L are constant; the error is the largest of |L - L0| / |L0|
/// and |E - E0| / E0.
FamilyError torque_free_box_error(const WorldSettings& settings, const ResponseModel& model);

/// A block on an incline (chapter 6, friction), seen in the incline's frame: a box 0.2 m
/// long and 0.1 m high (0.1 m deep), 1 kg, at rest on flat ground y = 0, with gravity tilted
/// by theta = 30 degrees, (g sin(theta), -g cos(theta)): the same motion as on a 30-degree
/// slope, and every engine builds it from axis-aligned shapes. Friction coefficient mu, the
/// same static and dynamic. Closed form: it sticks when tan(theta) <= mu; otherwise it slides
/// down the slope (+x) with a = g (sin(theta) - mu cos(theta)), x = a t^2 / 2, v = a t. The
/// family runs both: mu = 0.3 (slides, tan 30 degrees = 0.577) and mu = 0.8 (sticks).
struct Incline {
    double theta_degrees = 30.0, g = 9.81, mass = 1.0;
    double half_length = 0.1, half_height = 0.05, half_depth = 0.05;  ///< m
    double duration = 1.0;                                             ///< s
    static constexpr double mu_slides = 0.3, mu_sticks = 0.8;
    [[nodiscard]] double gravity_x() const;  ///< g sin(theta), down the slope
    [[nodiscard]] double gravity_y() const;  ///< -g cos(theta), into the slope
    /// The block's acceleration down the slope: 0 when tan(theta) <= mu, else g (sin - mu cos).
    [[nodiscard]] double acceleration(double mu) const;
    /// At time t: the larger of |x - a t^2 / 2| over the frictionless slide g sin(theta) t^2 / 2
    /// and |v - a t| over the frictionless speed g sin(theta) t (so that sticking, whose exact
    /// answer is 0, is measured against the same scale as sliding).
    [[nodiscard]] double error(double mu, double t, double x, double vx) const;
};

/// A solid ball (radius 0.1 m, 1 kg, I = 2/5 m r^2) set on the ground at v0 = 3 m/s without
/// spin, friction mu = 0.2 (static and dynamic), g = 9.81 m/s^2, for 1 s. Closed form: it slides,
/// v = v0 - mu g t, while friction spins it up, w = 5 mu g t / (2 r) (about -z for motion along
/// +x); at t* = 2 v0 / (7 mu g) (0.437 s) v = w r and from then on it rolls at 5/7 v0.
struct ThrownBall {
    double radius = 0.1, mass = 1.0, v0 = 3.0, mu = 0.2, g = 9.81, duration = 1.0;
    [[nodiscard]] double switch_time() const { return 2.0 * v0 / (7.0 * mu * g); }
    [[nodiscard]] double velocity(double t) const;  ///< m/s along +x
    [[nodiscard]] double position(double t) const;  ///< m along x, from 0
    [[nodiscard]] double spin(double t) const;      ///< rad/s about +z (negative: rolling towards +x)
    /// At time t: the larger of |v - v(t)| / v0, |w - w(t)| r / v0 and |x - x(t)| / (2 r).
    [[nodiscard]] double error(double t, double x, double vx, double spin_z) const;
};

/// The response model the workbook's friction families run with and the world it builds for
/// them: see friction_families.cpp, the one place that says how the workbook is given a
/// friction coefficient.
const ResponseModel& friction_model();
World friction_world(std::vector<RigidBody> bodies, WorldSettings settings, const ResponseModel& model, double mu);

FamilyError incline_error(const WorldSettings& settings, const ResponseModel& model);
FamilyError thrown_ball_error(const WorldSettings& settings, const ResponseModel& model);

/// A family for the bench: its id (file names), a title (figures), the chapter whose page
/// shows it, the chapter model it runs with, and its run.
struct Family {
    std::string id;
    std::string title;
    std::string chapter;
    ResponseModel model;
    FamilyError (*run)(const WorldSettings&, const ResponseModel&);
    bool gravity = true;   ///< false: no gravity, so the integrators move bodies alike and one is swept
    /// false: only discrete timing is swept (no contact, so the timing changes nothing; or a
    /// model that solves a step's contacts together, which needs discrete timing)
    bool contacts = true;
};

/// Every family with a closed form, in chapter order, each with its chapter's response model
/// from the table (chapter_model()).
std::vector<Family> families();

}  // namespace workbook::accuracy
