#include "families.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "models.hpp"
#include "workbook/time_series.hpp"

namespace workbook::accuracy {

namespace {

WorldSettings with_gravity(WorldSettings settings, double g) {
    settings.gravity = {0.0, -g, 0.0};
    return settings;
}

RigidBody ball(double mass, double radius, const Vector3& at, const Vector3& velocity, double restitution) {
    RigidBody b = make_sphere(mass, radius, at, velocity);
    b.restitution = restitution;
    return b;
}

/// Steps until the world clock reaches `end` (to the nearest step).
std::size_t run_until(World& world, double end) {
    const std::size_t steps = step_count(end, world.settings().time_step);
    for (std::size_t i = 0; i < steps; ++i) world.step();
    return steps;
}

/// A body's position and velocity along x against free flight from `x0` at `v_before`, then
/// `v_after` from `t_hit` on; the error as max(|dv| / v_scale, |dx| / x_scale).
double straight_line_error(double x, double vx, double x0, double v_before, double v_after, double t_hit, double t,
                           double v_scale, double x_scale) {
    const double exact_x = x0 + v_before * t_hit + v_after * (t - t_hit);
    return std::max(std::abs(vx - v_after) / v_scale, std::abs(x - exact_x) / x_scale);
}

/// The same for a body of the workbook, which must also stay on the x axis.
double off_axis(const RigidBody& body) { return std::hypot(body.position.y, body.position.z); }

}  // namespace

double BouncingBall::bounce_time(int k) const {
    const double fall = std::sqrt(2.0 * h0 / g);
    double sum = 0.0;
    for (int j = 1; j < k; ++j) sum += std::pow(restitution, j);
    return fall * (1.0 + 2.0 * sum);
}

double BouncingBall::apex(int k) const { return std::pow(restitution, 2 * k) * h0; }

World BouncingBall::world(WorldSettings settings, const ResponseModel& model) const {
    RigidBody ground = make_immovable_plane({0.0, 1.0, 0.0}, {});
    ground.restitution = 1.0;
    return World({ball(1.0, radius, {0.0, h0 + radius, 0.0}, {}, restitution), ground}, with_gravity(settings, g), model);
}

std::pair<double, double> BouncingBall::errors(std::span<const Bounce> seen, int count) const {
    if (static_cast<int>(seen.size()) < count) return {1.0, 0.0};
    double apex_error = 0.0, time_error = 0.0;
    for (int k = 1; k <= count; ++k) {
        const Bounce& b = seen[static_cast<std::size_t>(k - 1)];
        apex_error = std::max(apex_error, std::abs(b.apex - apex(k)) / apex(k));
        time_error = std::max(time_error, std::abs(b.time - bounce_time(k)));
    }
    return {apex_error, time_error};
}

void BounceObserver::after_step(double t, double y, double vy) {
    if (previous_vy_ <= 0.0 && vy > 0.0) {
        const double height = y - ball_.radius;
        const double tau = (std::sqrt(vy * vy + 2.0 * ball_.g * std::max(height, 0.0)) - vy) / ball_.g;
        bounces_.push_back({t - tau, height + vy * vy / (2.0 * ball_.g)});
    }
    previous_vy_ = vy;
}

std::vector<Bounce> observe_bounces(World& world, const BouncingBall& ball, int count, double max_time) {
    BounceObserver observer(ball, world.bodies()[0].velocity.y);
    while (static_cast<int>(observer.bounces().size()) < count && world.time() < max_time) {
        world.step();
        const RigidBody& b = world.bodies()[0];
        observer.after_step(world.time(), b.position.y, b.velocity.y);
    }
    return observer.bounces();
}

FamilyError bouncing_ball_error(const WorldSettings& settings, const ResponseModel& model, int bounces) {
    const BouncingBall ball;
    World world = ball.world(settings, model);
    const std::vector<Bounce> seen = observe_bounces(world, ball, bounces, ball.bounce_time(bounces) + 1.0);
    FamilyError result;
    result.steps = world.steps_taken();
    std::tie(result.error, result.time_error) = ball.errors(seen, bounces);
    return result;
}

double HeadOn::v1_after() const { return (m1 * v1 + m2 * v2 - m2 * restitution * (v1 - v2)) / (m1 + m2); }
double HeadOn::v2_after() const { return (m1 * v1 + m2 * v2 + m1 * restitution * (v1 - v2)) / (m1 + m2); }

double HeadOn::error(double t, double xa, double va, double xb, double vb) const {
    const double t_hit = time_of_impact();
    return std::max(straight_line_error(xa, va, x1(), v1, v1_after(), t_hit, t, v1 - v2, 2.0 * radius),
                    straight_line_error(xb, vb, x2(), v2, v2_after(), t_hit, t, v1 - v2, 2.0 * radius));
}

FamilyError head_on_error(const WorldSettings& settings, const ResponseModel& model, const HeadOn& pair) {
    World world({ball(pair.m1, pair.radius, {pair.x1(), 0, 0}, {pair.v1, 0, 0}, pair.restitution),
                 ball(pair.m2, pair.radius, {pair.x2(), 0, 0}, {pair.v2, 0, 0}, pair.restitution)},
                with_gravity(settings, 0.0), model);
    FamilyError result;
    result.steps = run_until(world, 1.0);
    const RigidBody& a = world.bodies()[0];
    const RigidBody& b = world.bodies()[1];
    result.error = std::max({pair.error(world.time(), a.position.x, a.velocity.x, b.position.x, b.velocity.x),
                             off_axis(a) / (2.0 * pair.radius), off_axis(b) / (2.0 * pair.radius)});
    return result;
}

double Cradle::start_x(int i) const { return i == 0 ? -2.0 * radius - gap : 2.0 * radius * (i - 1); }

double Cradle::error(double t, std::span<const double> x, std::span<const double> vx) const {
    const double t_hit = gap / speed;
    double worst = straight_line_error(x[0], vx[0], start_x(0), speed, 0.0, t_hit, t, speed, radius);
    for (int i = 1; i < row; ++i) {  // the inner balls of the row stay put
        const auto k = static_cast<std::size_t>(i);
        worst = std::max(worst, straight_line_error(x[k], vx[k], start_x(i), 0.0, 0.0, t_hit, t, speed, radius));
    }
    return std::max(worst, straight_line_error(x[row], vx[row], start_x(row), 0.0, speed, t_hit, t, speed, radius));
}

FamilyError cradle_error(const WorldSettings& settings, const ResponseModel& model) {
    const Cradle cradle;
    std::vector<RigidBody> balls;
    for (int i = 0; i <= Cradle::row; ++i)
        balls.push_back(ball(1.0, cradle.radius, {cradle.start_x(i), 0, 0}, {i == 0 ? cradle.speed : 0.0, 0, 0}, 1.0));
    World world(balls, with_gravity(settings, 0.0), model);
    FamilyError result;
    result.steps = run_until(world, 1.0);
    double x[Cradle::row + 1], vx[Cradle::row + 1];
    double off = 0.0;
    for (std::size_t i = 0; i <= Cradle::row; ++i) {
        x[i] = world.bodies()[i].position.x;
        vx[i] = world.bodies()[i].velocity.x;
        off = std::max(off, off_axis(world.bodies()[i]) / cradle.radius);
    }
    result.error = std::max(cradle.error(world.time(), x, vx), off);
    return result;
}

FamilyError stacked_drop_error(const WorldSettings& settings, const ResponseModel& model) {
    // A 0.1 kg ball resting on a 1 kg ball, dropped with the big ball's bottom 1 m above the
    // ground, e = 1 everywhere. Taking the two impacts one after the other (ground, then the
    // pair), the small ball leaves at v (3 M - m) / (M + m), v = sqrt(2 g h0).
    const double g = 9.81, h0 = 1.0, big_r = 0.2, small_r = 0.05, big_m = 1.0, small_m = 0.1;
    RigidBody ground = make_immovable_plane({0.0, 1.0, 0.0}, {});
    World world({ball(big_m, big_r, {0, h0 + big_r, 0}, {}, 1.0),
                 ball(small_m, small_r, {0, h0 + 2.0 * big_r + small_r, 0}, {}, 1.0), ground},
                with_gravity(settings, g), model);
    const double v = std::sqrt(2.0 * g * h0);
    const double launch = v * (3.0 * big_m - small_m) / (big_m + small_m);
    const double rise = launch * launch / (2.0 * g);
    const double exact_apex = 2.0 * big_r + small_r + rise;

    FamilyError result;
    bool rising = false;
    while (world.time() < 10.0) {
        world.step();
        const RigidBody& small = world.bodies()[1];
        if (small.velocity.y > 0.0) rising = true;
        if (rising && small.velocity.y <= 0.0) {
            const double apex = small.position.y + small.velocity.y * small.velocity.y / (2.0 * g);
            result.error = std::abs(apex - exact_apex) / rise;
            break;
        }
    }
    result.steps = world.steps_taken();
    return result;
}

FamilyError resting_stack_error(const WorldSettings& settings, const ResponseModel& model, int balls) {
    const double r = 0.1;
    std::vector<RigidBody> bodies{make_immovable_plane({0.0, 1.0, 0.0}, {})};
    for (int i = 0; i < balls; ++i) bodies.push_back(ball(1.0, r, {0.0, r * (2 * i + 1), 0.0}, {}, 0.0));
    World world(bodies, with_gravity(settings, 9.81), model);
    const std::size_t steps = step_count(1.0, settings.time_step);
    FamilyError result;
    result.error = 0.0;
    for (std::size_t n = 0; n < steps; ++n) {
        world.step();
        for (int i = 0; i < balls; ++i) {
            const double sink = r * (2 * i + 1) - world.bodies()[static_cast<std::size_t>(i) + 1].position.y;
            result.error = std::max(result.error, sink / r);
        }
    }
    result.steps = steps;
    return result;
}

std::vector<Family> families() {
    const ResponseModel inelastic = chapter_model("inelastic");
    const ResponseModel linear = chapter_model("linear-impulse");
    const ResponseModel angular = chapter_model("angular-impulse");
    return {
        {"head-on-inelastic", "Head-on pair, 1 kg and 3 kg, perfectly inelastic: velocities and positions after 1 s",
         "inelastic", inelastic,
         [](const WorldSettings& s, const ResponseModel& m) {
             HeadOn pair;
             pair.restitution = 0.0;
             return head_on_error(s, m, pair);
         },
         false, true},
        {"resting-stack", "Three balls stacked on the ground, at rest: the deepest a ball sinks in 1 s, over its radius",
         "projection", inelastic_with_projection(),
         [](const WorldSettings& s, const ResponseModel& m) { return resting_stack_error(s, m, 3); }},
        {"bouncing-ball", "Bouncing ball, e = 0.8: apexes of the first 10 bounces against e^{2k} h_0", "linear-impulse",
         linear, [](const WorldSettings& s, const ResponseModel& m) { return bouncing_ball_error(s, m, 10); }},
        {"head-on", "Head-on pair, 1 kg and 3 kg, e = 0.5: velocities and positions after 1 s", "linear-impulse", linear,
         [](const WorldSettings& s, const ResponseModel& m) { return head_on_error(s, m); }, false, true},
        {"cradle", "Newton's cradle, five balls, e = 1: velocities and positions after 1 s", "linear-impulse", linear,
         &cradle_error, false, true},
        {"stacked-drop", "Stacked-ball drop, 0.1 kg on 1 kg, e = 1: the small ball's apex", "linear-impulse", linear,
         &stacked_drop_error},
        {"tilted-rod", "Tilted rod, 2 kg, 1 m, 30 degrees, lands at 3 m/s, e = 0.5: velocity and spin after the impact",
         "angular-impulse", angular, &tilted_rod_error},
        {"torque-free-box", "Box spinning freely near its middle axis for 10 s: drift of |L| and of E", "angular-impulse",
         angular, &torque_free_box_error, false, false},
        // Chapter 6's: the model and the way the coefficient is given are friction_families.cpp's
        // (chapter 5's contact solver until chapter 6 is merged), whose solver needs discrete timing.
        {"incline", "Block on a 30-degree incline, mu = 0.3 (slides) and 0.8 (sticks): slide and speed after 1 s",
         "friction", friction_model(), &incline_error, true, false},
        {"thrown-ball", "Ball thrown at 3 m/s without spin, mu = 0.2: slides, then rolls at 5/7 v0; state after 1 s",
         "friction", friction_model(), &thrown_ball_error, true, false},
    };
}

}  // namespace workbook::accuracy
