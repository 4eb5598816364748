#include "peers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "families.hpp"
#include "workbook/time_series.hpp"

namespace workbook::accuracy {

namespace {

FamilyError bouncing_ball(const PeerEngine& engine, double dt) {
    const BouncingBall ball;
    PeerScene scene;
    scene.balls.push_back({1.0, ball.radius, 0.0, ball.h0 + ball.radius, 0.0, 0.0});
    scene.ground = true;
    scene.g = ball.g;
    scene.restitution = ball.restitution;
    const auto world = engine.make(scene, dt);
    constexpr int bounces = 10;
    BounceObserver observer(ball, 0.0);
    const double end = ball.bounce_time(bounces) + 1.0;
    FamilyError result;
    while (static_cast<int>(observer.bounces().size()) < bounces && static_cast<double>(result.steps) * dt < end) {
        world->step();
        ++result.steps;
        const PeerState s = world->body(0);
        observer.after_step(static_cast<double>(result.steps) * dt, s.y, s.vy);
    }
    std::tie(result.error, result.time_error) = ball.errors(observer.bounces(), bounces);
    return result;
}

FamilyError head_on(const PeerEngine& engine, double dt) {
    const HeadOn pair;
    PeerScene scene;
    scene.balls.push_back({pair.m1, pair.radius, pair.x1(), 0.0, pair.v1, 0.0});
    scene.balls.push_back({pair.m2, pair.radius, pair.x2(), 0.0, pair.v2, 0.0});
    scene.restitution = pair.restitution;
    const auto world = engine.make(scene, dt);
    FamilyError result;
    result.steps = step_count(1.0, dt);
    for (std::size_t n = 0; n < result.steps; ++n) world->step();
    const PeerState a = world->body(0), b = world->body(1);
    const double off = std::max(std::abs(a.y), std::abs(b.y)) / (2.0 * pair.radius);
    result.error = std::max(pair.error(static_cast<double>(result.steps) * dt, a.x, a.vx, b.x, b.vx), off);
    return result;
}

FamilyError cradle(const PeerEngine& engine, double dt) {
    const Cradle cradle;
    PeerScene scene;
    for (int i = 0; i <= Cradle::row; ++i)
        scene.balls.push_back({1.0, cradle.radius, cradle.start_x(i), 0.0, i == 0 ? cradle.speed : 0.0, 0.0});
    scene.restitution = 1.0;
    const auto world = engine.make(scene, dt);
    FamilyError result;
    result.steps = step_count(1.0, dt);
    for (std::size_t n = 0; n < result.steps; ++n) world->step();
    double x[Cradle::row + 1], vx[Cradle::row + 1];
    double off = 0.0;
    for (std::size_t i = 0; i <= Cradle::row; ++i) {
        const PeerState s = world->body(i);
        x[i] = s.x;
        vx[i] = s.vx;
        off = std::max(off, std::abs(s.y) / cradle.radius);
    }
    result.error = std::max(cradle.error(static_cast<double>(result.steps) * dt, x, vx), off);
    return result;
}

FamilyError incline(const PeerEngine& engine, double dt) {
    const Incline incline;
    FamilyError result;
    result.error = 0.0;
    for (double mu : {Incline::mu_slides, Incline::mu_sticks}) {
        PeerScene scene;
        scene.boxes.push_back({incline.mass, incline.half_length, incline.half_height, incline.half_depth, 0.0,
                               incline.half_height, 0.0, 0.0});
        scene.ground = true;
        scene.g = -incline.gravity_y();
        scene.gx = incline.gravity_x();
        scene.restitution = 0.0;
        scene.friction = mu;
        const auto world = engine.make(scene, dt);
        const std::size_t steps = step_count(incline.duration, dt);
        for (std::size_t n = 0; n < steps; ++n) world->step();
        const PeerState s = world->body(0);
        result.error = std::max(result.error, incline.error(mu, static_cast<double>(steps) * dt, s.x, s.vx));
        result.steps += steps;
    }
    return result;
}

FamilyError thrown_ball(const PeerEngine& engine, double dt) {
    const ThrownBall thrown;
    PeerScene scene;
    scene.balls.push_back({thrown.mass, thrown.radius, 0.0, thrown.radius, thrown.v0, 0.0});
    scene.ground = true;
    scene.g = thrown.g;
    scene.restitution = 0.0;
    scene.friction = thrown.mu;
    const auto world = engine.make(scene, dt);
    FamilyError result;
    result.steps = step_count(thrown.duration, dt);
    for (std::size_t n = 0; n < result.steps; ++n) world->step();
    const PeerState s = world->body(0);
    result.error = thrown.error(static_cast<double>(result.steps) * dt, s.x, s.vx, s.spin);
    return result;
}

using PeerFamily = FamilyError (*)(const PeerEngine&, double);

PeerFamily peer_family(const std::string& id) {
    if (id == "bouncing-ball") return &bouncing_ball;
    if (id == "head-on") return &head_on;
    if (id == "cradle") return &cradle;
    if (id == "incline") return &incline;
    if (id == "thrown-ball") return &thrown_ball;
    return nullptr;
}

}  // namespace

std::vector<PeerEngine> peer_engines() {
    std::vector<PeerEngine> engines;
#ifdef WORKBOOK_HAVE_CHIPMUNK
    engines.push_back(chipmunk_peer());
#endif
#ifdef WORKBOOK_HAVE_BOX2D
    engines.push_back(box2d_peer());
#endif
#ifdef WORKBOOK_HAVE_BULLET
    engines.push_back(bullet_peer());
#endif
    return engines;
}

bool peers_run(const std::string& family_id) { return peer_family(family_id) != nullptr; }

FamilyError peer_family_error(const std::string& family_id, const PeerEngine& engine, double frame_step) {
    const PeerFamily run = peer_family(family_id);
    if (run == nullptr) throw std::invalid_argument("the peers do not run the family \"" + family_id + "\"");
    return run(engine, frame_step);
}

std::vector<BenchPoint> peer_points(const std::string& family_id) {
    std::vector<BenchPoint> points;
    const PeerFamily run = peer_family(family_id);
    if (run == nullptr) return points;
    for (const PeerEngine& engine : peer_engines())
        for (int frames_per_second : frame_rates()) {
            BenchPoint point;
            point.family = family_id;
            point.engine = engine.name;
            point.frame_step = 1.0 / frames_per_second;
            point.result = run(engine, point.frame_step);
            point.seconds = seconds_per_run([&] { (void)run(engine, point.frame_step); });
            points.push_back(point);
        }
    return points;
}

}  // namespace workbook::accuracy
