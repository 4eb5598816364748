#include "peers.hpp"

#include <algorithm>
#include <cmath>
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
        const PeerState s = world->ball(0);
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
    const PeerState a = world->ball(0), b = world->ball(1);
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
        const PeerState s = world->ball(i);
        x[i] = s.x;
        vx[i] = s.vx;
        off = std::max(off, std::abs(s.y) / cradle.radius);
    }
    result.error = std::max(cradle.error(static_cast<double>(result.steps) * dt, x, vx), off);
    return result;
}

using PeerFamily = FamilyError (*)(const PeerEngine&, double);

PeerFamily peer_family(const std::string& id) {
    if (id == "bouncing-ball") return &bouncing_ball;
    if (id == "head-on") return &head_on;
    if (id == "cradle") return &cradle;
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
