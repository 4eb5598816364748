#include "families.hpp"

#include <algorithm>
#include <cmath>

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

/// Body i's position and velocity against free flight from `x0` at `v_before`, then `v_after`
/// from `t_hit` on; the error as max(|dv| / v_scale, |dx| / x_scale).
double straight_line_error(const RigidBody& body, double x0, double v_before, double v_after, double t_hit, double t,
                           double v_scale, double x_scale) {
    const double exact_x = x0 + v_before * t_hit + v_after * (t - t_hit);
    const double dv = length(body.velocity - Vector3{v_after, 0.0, 0.0});
    const double dx = length(body.position - Vector3{exact_x, 0.0, 0.0});
    return std::max(dv / v_scale, dx / x_scale);
}

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

std::vector<Bounce> observe_bounces(World& world, const BouncingBall& ball, int count, double max_time) {
    std::vector<Bounce> bounces;
    double previous_vy = world.bodies()[0].velocity.y;
    while (static_cast<int>(bounces.size()) < count && world.time() < max_time) {
        world.step();
        const RigidBody& b = world.bodies()[0];
        const double vy = b.velocity.y;
        if (previous_vy <= 0.0 && vy > 0.0) {
            const double height = b.position.y - ball.radius;
            const double tau = (std::sqrt(vy * vy + 2.0 * ball.g * std::max(height, 0.0)) - vy) / ball.g;
            bounces.push_back({world.time() - tau, height + vy * vy / (2.0 * ball.g)});
        }
        previous_vy = vy;
    }
    return bounces;
}

FamilyError bouncing_ball_error(const WorldSettings& settings, const ResponseModel& model, int bounces) {
    const BouncingBall ball;
    World world = ball.world(settings, model);
    const std::vector<Bounce> seen = observe_bounces(world, ball, bounces, ball.bounce_time(bounces) + 1.0);
    FamilyError result;
    result.steps = world.steps_taken();
    if (static_cast<int>(seen.size()) < bounces) return result;
    result.error = 0.0;
    for (int k = 1; k <= bounces; ++k) {
        const Bounce& b = seen[static_cast<std::size_t>(k - 1)];
        result.error = std::max(result.error, std::abs(b.apex - ball.apex(k)) / ball.apex(k));
        result.time_error = std::max(result.time_error, std::abs(b.time - ball.bounce_time(k)));
    }
    return result;
}

FamilyError head_on_error(const WorldSettings& settings, const ResponseModel& model) {
    // 1 kg at 2 m/s meets 3 kg at -1 m/s, e = 0.5, surfaces 0.3071 m apart: impact at 0.10237 s.
    const double m1 = 1.0, m2 = 3.0, v1 = 2.0, v2 = -1.0, e = 0.5, r = 0.5, gap = 0.3071;
    const double x1 = -(2.0 * r + gap), x2 = 0.0;
    const double t_hit = gap / (v1 - v2);
    const double p = m1 * v1 + m2 * v2;
    const double v1_after = (p - m2 * e * (v1 - v2)) / (m1 + m2);
    const double v2_after = (p + m1 * e * (v1 - v2)) / (m1 + m2);
    World world({ball(m1, r, {x1, 0, 0}, {v1, 0, 0}, e), ball(m2, r, {x2, 0, 0}, {v2, 0, 0}, e)},
                with_gravity(settings, 0.0), model);
    FamilyError result;
    result.steps = run_until(world, 1.0);
    const double t = world.time();
    result.error = std::max(straight_line_error(world.bodies()[0], x1, v1, v1_after, t_hit, t, v1 - v2, 2.0 * r),
                            straight_line_error(world.bodies()[1], x2, v2, v2_after, t_hit, t, v1 - v2, 2.0 * r));
    return result;
}

FamilyError cradle_error(const WorldSettings& settings, const ResponseModel& model) {
    const double r = 0.1, v = 1.0, gap = 0.0513;
    std::vector<RigidBody> balls{ball(1.0, r, {-2.0 * r - gap, 0, 0}, {v, 0, 0}, 1.0)};
    for (int i = 0; i < 4; ++i) balls.push_back(ball(1.0, r, {2.0 * r * i, 0, 0}, {}, 1.0));
    World world(balls, with_gravity(settings, 0.0), model);
    FamilyError result;
    result.steps = run_until(world, 1.0);
    const double t = world.time();
    const double t_hit = gap / v;
    double error = straight_line_error(world.bodies()[0], -2.0 * r - gap, v, 0.0, t_hit, t, v, r);
    for (int i = 1; i < 4; ++i)  // the three inner balls of the row, at 2 r (i - 1), stay put
        error = std::max(error, straight_line_error(world.bodies()[static_cast<std::size_t>(i)], 2.0 * r * (i - 1), 0.0,
                                                    0.0, t_hit, t, v, r));
    error = std::max(error, straight_line_error(world.bodies()[4], 6.0 * r, 0.0, v, t_hit, t, v, r));
    result.error = error;
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

std::vector<Family> families() {
    return {{"bouncing-ball", "Bouncing ball, e = 0.8: apexes of the first 10 bounces against e^{2k} h_0",
             [](const WorldSettings& s, const ResponseModel& m) { return bouncing_ball_error(s, m, 10); }},
            {"head-on", "Head-on pair, 1 kg and 3 kg, e = 0.5: velocities and positions after 1 s", &head_on_error},
            {"cradle", "Newton's cradle, five balls, e = 1: velocities and positions after 1 s", &cradle_error},
            {"stacked-drop", "Stacked-ball drop, 0.1 kg on 1 kg, e = 1: the small ball's apex", &stacked_drop_error}};
}

}  // namespace workbook::accuracy
