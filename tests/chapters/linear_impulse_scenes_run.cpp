// Measurements behind chapter 3's scene checks (see linear_impulse_scenes.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "linear-impulse.hpp"
#include "linear_impulse_scenes.hpp"
#include "workbook/response_model.hpp"
#include "workbook/scene.hpp"
#include "workbook/world.hpp"

namespace workbook::chapter3 {

namespace {

Scene load(const std::string& relative_path) { return load_scene(std::filesystem::path(WORKBOOK_SOURCE_DIR) / relative_path); }

World world_of(const Scene& scene) { return make_world(scene, *find_response_model(scene.responder)); }

std::vector<double> x_velocities(std::span<const RigidBody> bodies) {
    std::vector<double> v;
    for (const RigidBody& b : bodies) v.push_back(b.velocity.x);
    return v;
}

}  // namespace

Run run_scene(const std::string& relative_path) { return run_scene_with_slop(relative_path, -1.0); }

Run run_scene_with_slop(const std::string& relative_path, double slop) {
    Scene scene = load(relative_path);
    if (slop >= 0.0) scene.settings.position_correction.slop = slop;
    World world = world_of(scene);
    Run run;
    const auto steps = static_cast<long>(std::llround(scene.duration / scene.settings.time_step));
    for (long i = 0; i < steps; ++i) {
        world.step();
        if (world.probes().response_energy_change != 0.0 || !world.contacts().empty()) ++run.responses;
    }
    run.bodies.assign(world.bodies().begin(), world.bodies().end());
    run.last = world.probes();
    return run;
}

std::vector<CartsCase> carts_cases() {
    const std::string folder = "chapters/linear-impulse/scenes/";
    return {{folder + "head-on-carts-e0.json", 0.0}, {folder + "head-on-carts-e05.json", 0.5},
            {folder + "head-on-carts-e08.json", 0.8}, {folder + "head-on-carts-e1.json", 1.0}};
}

BounceReport bouncing_ball_report() {
    const Scene scene = load("chapters/linear-impulse/scenes/bouncing-ball.json");
    World world = world_of(scene);
    const double radius = scene.bodies[0].shape.radius;
    const auto steps = static_cast<long>(std::llround(scene.duration / scene.settings.time_step));
    BounceReport report;
    bool bounced = false;
    double previous_vy = 0.0;
    for (long i = 0; i < steps; ++i) {
        world.step();
        const RigidBody& ball = world.bodies()[0];
        if (previous_vy < 0.0 && ball.velocity.y > 0.0) bounced = true;
        // An apex: the vertical velocity turns from up to down after a bounce.
        if (bounced && previous_vy > 0.0 && ball.velocity.y <= 0.0) {
            report.apexes.push_back(ball.position.y - radius);
            bounced = false;
        }
        previous_vy = ball.velocity.y;
    }
    return report;
}

CradleOrders cradle_orders() {
    // The cradle pressed together: each neighbour overlaps by 1 micrometre, so detection
    // reports all four contacts in one step and the order of the pass decides.
    const Scene scene = load("chapters/linear-impulse/scenes/newtons-cradle.json");
    std::vector<RigidBody> pressed = scene.bodies;
    for (std::size_t i = 0; i < pressed.size(); ++i) pressed[i].position = {0.25 * static_cast<double>(i) - 1e-6 * static_cast<double>(i), 0, 0};
    auto pass = [](World& world, bool reverse) {
        world.detect();
        auto contacts = std::vector<Contact>(world.contacts().begin(), world.contacts().end());
        if (reverse) std::reverse(contacts.begin(), contacts.end());
        for (const Contact& c : contacts) linear_impulse::resolve(world.bodies()[c.body1], world.bodies()[c.body2], c);
    };
    CradleOrders out;
    World forward(pressed, WorldSettings{}, ResponseModel{});
    pass(forward, false);
    out.forward_after_one_step = x_velocities(forward.bodies());
    World reverse(pressed, WorldSettings{}, ResponseModel{});
    pass(reverse, true);
    out.reverse_after_one_step = x_velocities(reverse.bodies());
    out.reverse_steps_to_finish = 1;
    while (reverse.bodies()[4].velocity.x == 0.0 && out.reverse_steps_to_finish < 10) {
        pass(reverse, true);
        ++out.reverse_steps_to_finish;
    }
    out.reverse_final = x_velocities(reverse.bodies());
    // All at once: contact 1 separates at e times its approach speed (u2 - u1 = 1 m/s), the
    // other three, which did not approach, end with no relative normal velocity (u2 = ... = u5),
    // and momentum is kept (u1 + 4 u = 1 kg m/s / 1 kg): u = 2/5, u1 = -3/5.
    const double block = 2.0 / 5.0;
    out.simultaneous = {block - 1.0, block, block, block, block};
    return out;
}

StackReport stacked_balls_report() {
    const Scene scene = load("chapters/linear-impulse/scenes/stacked-balls.json");
    World world = world_of(scene);
    const double big = scene.bodies[0].mass();
    const double small = scene.bodies[1].mass();
    const double start = scene.bodies[1].position.y;
    StackReport report;
    report.ideal_factor = std::pow((3.0 * big - small) / (big + small), 2.0);
    double hit_height = 0.0;
    double apex = -1.0;
    const auto steps = static_cast<long>(std::llround(scene.duration / scene.settings.time_step));
    for (long i = 0; i < steps; ++i) {
        const double before = world.bodies()[1].velocity.y;
        world.step();
        const RigidBody& ball = world.bodies()[1];
        if (hit_height == 0.0 && before < 0.0 && ball.velocity.y > 0.0) hit_height = ball.position.y;
        if (hit_height != 0.0) apex = std::max(apex, ball.position.y);
    }
    report.fall = start - hit_height;
    report.rise = apex - hit_height;
    report.factor = report.rise / report.fall;
    return report;
}

}  // namespace workbook::chapter3
