// The pile (pile.hpp) in Box2D 2.4.1 (Debian's libbox2d-dev, single precision), on its
// defaults: sleeping on, 8 velocity and 3 position iterations a step as its manual recommends,
// its built-in linear slop of 5 mm, and edges that carry its polygon skin of 1 cm (a disc rests
// on an edge with its surface that far above it). Set here: no friction, e = 0.
#include <box2d/box2d.h>

#include <numbers>
#include <vector>

#include "pile.hpp"

namespace workbook::bench {

PileResult run_pile_box2d(const Pile& pile, int steps, double budget) {
    b2World world(b2Vec2(0.0f, static_cast<float>(-Pile::gravity)));
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(Pile::radius);
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.density = static_cast<float>(Pile::mass / (std::numbers::pi * Pile::radius * Pile::radius));
    fixture.friction = 0.0f;
    fixture.restitution = 0.0f;
    std::vector<b2Body*> bodies;
    for (std::size_t i = 0; i < pile.x.size(); ++i) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(static_cast<float>(pile.x[i]), static_cast<float>(pile.y[i]));
        b2Body* body = world.CreateBody(&def);
        body->CreateFixture(&fixture);
        bodies.push_back(body);
    }
    b2BodyDef box_def;
    b2Body* box = world.CreateBody(&box_def);
    const auto h = static_cast<float>(pile.width / 2), top = static_cast<float>(pile.wall_height());
    const b2Vec2 ends[3][2] = {{b2Vec2(-h, 0), b2Vec2(h, 0)}, {b2Vec2(-h, 0), b2Vec2(-h, top)}, {b2Vec2(h, 0), b2Vec2(h, top)}};
    for (const auto& end : ends) {
        b2EdgeShape edge;
        edge.SetTwoSided(end[0], end[1]);
        b2FixtureDef wall;
        wall.shape = &edge;
        wall.friction = 0.0f;
        wall.restitution = 0.0f;
        box->CreateFixture(&wall);
    }
    const double seconds = timed_steps(steps, budget, [&world] { world.Step(static_cast<float>(Pile::time_step), 8, 3); });
    std::vector<double> x, y, vx, vy;
    for (b2Body* body : bodies) {
        const b2Vec2 p = body->GetPosition(), v = body->GetLinearVelocity();
        x.push_back(static_cast<double>(p.x));
        y.push_back(static_cast<double>(p.y));
        vx.push_back(static_cast<double>(v.x));
        vy.push_back(static_cast<double>(v.y));
    }
    return finish_pile(pile, seconds, x, y, vx, vy);
}

}  // namespace workbook::bench
