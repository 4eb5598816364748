// The gas in Box2D 2.4.1 (Debian's libbox2d-dev): 8 velocity and 3 position iterations as
// its manual recommends, restitution threshold 0 so that slow impacts bounce too, sleeping off.
#include <box2d/box2d.h>

#include <ctime>
#include <numbers>
#include <vector>

#include "gas.hpp"

namespace workbook::bench {

GasResult run_box2d(const Gas& gas, int steps) {
    b2World world(b2Vec2(0.0f, 0.0f));
    world.SetAllowSleeping(false);
    std::vector<b2Body*> bodies;
    bodies.reserve(gas.discs.size());
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(Gas::radius);
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.density = static_cast<float>(Gas::mass / (std::numbers::pi * Gas::radius * Gas::radius));
    fixture.friction = 0.0f;
    fixture.restitution = 1.0f;
    fixture.restitutionThreshold = 0.0f;
    for (const Disc& d : gas.discs) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(static_cast<float>(d.x), static_cast<float>(d.y));
        def.linearVelocity.Set(static_cast<float>(d.vx), static_cast<float>(d.vy));
        def.allowSleep = false;
        b2Body* body = world.CreateBody(&def);
        body->CreateFixture(&fixture);
        bodies.push_back(body);
    }
    b2BodyDef wall_def;
    b2Body* walls = world.CreateBody(&wall_def);
    const auto h = static_cast<float>(gas.side / 2);
    const b2Vec2 corners[4] = {b2Vec2(-h, -h), b2Vec2(h, -h), b2Vec2(h, h), b2Vec2(-h, h)};
    for (int i = 0; i < 4; ++i) {
        b2EdgeShape edge;
        edge.SetTwoSided(corners[i], corners[(i + 1) % 4]);
        b2FixtureDef wall;
        wall.shape = &edge;
        wall.friction = 0.0f;
        wall.restitution = 1.0f;
        wall.restitutionThreshold = 0.0f;
        walls->CreateFixture(&wall);
    }
    auto energy = [&bodies] {
        double sum = 0.0;
        for (b2Body* body : bodies) sum += static_cast<double>(body->GetLinearVelocity().LengthSquared());
        return kinetic(sum);
    };
    GasResult result;
    result.energy_before = energy();
    const std::clock_t start = std::clock();
    for (int i = 0; i < steps; ++i) world.Step(static_cast<float>(Gas::time_step), 8, 3);
    result.seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    result.energy_after = energy();
    for (b2Body* body : bodies) {
        const b2Vec2 p = body->GetPosition();
        if (!inside(gas, static_cast<double>(p.x), static_cast<double>(p.y))) ++result.escaped;
    }
    return result;
}

}  // namespace workbook::bench
