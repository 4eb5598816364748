// Box2D 2.4 on the accuracy bench (peers.hpp). Box2D computes in single precision.
#include <box2d/box2d.h>

#include <numbers>
#include <string>
#include <vector>

#include "peers.hpp"

namespace workbook::accuracy {

namespace {

class Box2dWorld final : public PeerWorld {
public:
    Box2dWorld(const PeerScene& scene, double frame_step)
        : world_(b2Vec2(static_cast<float>(scene.gx), static_cast<float>(-scene.g))), dt_(static_cast<float>(frame_step)) {
        world_.SetAllowSleeping(false);
        // Box2D takes the larger of two fixtures' restitutions and the square root of the
        // product of their frictions: e and mu on every fixture give e and mu. Its restitution
        // threshold (default 1 m/s, below which it does not bounce) is off.
        b2FixtureDef fixture;
        fixture.friction = static_cast<float>(scene.friction);
        fixture.restitution = static_cast<float>(scene.restitution);
        fixture.restitutionThreshold = 0.0f;
        auto add_body = [this](double x, double y, double vx, double vy) {
            b2BodyDef def;
            def.type = b2_dynamicBody;
            def.position.Set(static_cast<float>(x), static_cast<float>(y));
            def.linearVelocity.Set(static_cast<float>(vx), static_cast<float>(vy));
            def.allowSleep = false;
            return bodies_.emplace_back(world_.CreateBody(&def));
        };
        for (const PeerBall& b : scene.balls) {
            b2Body* body = add_body(b.x, b.y, b.vx, b.vy);
            b2CircleShape circle;
            circle.m_radius = static_cast<float>(b.radius);
            fixture.shape = &circle;
            fixture.density = static_cast<float>(b.mass / (std::numbers::pi * b.radius * b.radius));
            body->CreateFixture(&fixture);
            // A solid sphere's moment, 2/5 m r^2, not a disc's (peers.hpp).
            b2MassData mass{static_cast<float>(b.mass), b2Vec2(0.0f, 0.0f), static_cast<float>(0.4 * b.mass * b.radius * b.radius)};
            body->SetMassData(&mass);
        }
        for (const PeerBox& b : scene.boxes) {
            b2Body* body = add_body(b.x, b.y, b.vx, b.vy);
            b2PolygonShape box;
            box.SetAsBox(static_cast<float>(b.half_width), static_cast<float>(b.half_height));
            fixture.shape = &box;
            fixture.density = static_cast<float>(b.mass / (4.0 * b.half_width * b.half_height));
            body->CreateFixture(&fixture);
        }
        if (scene.ground) {
            b2BodyDef def;
            b2Body* ground = world_.CreateBody(&def);
            b2EdgeShape edge;
            edge.SetTwoSided(b2Vec2(-100.0f, 0.0f), b2Vec2(100.0f, 0.0f));
            fixture.shape = &edge;
            fixture.density = 0.0f;
            ground->CreateFixture(&fixture);
        }
    }
    // The iterations Box2D's manual recommends: 8 for velocities, 3 for positions.
    void step() override { world_.Step(dt_, 8, 3); }
    [[nodiscard]] PeerState body(std::size_t index) const override {
        const b2Vec2 p = bodies_[index]->GetPosition();
        const b2Vec2 v = bodies_[index]->GetLinearVelocity();
        return {static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(v.x), static_cast<double>(v.y),
                static_cast<double>(bodies_[index]->GetAngularVelocity())};
    }

private:
    b2World world_;
    float dt_;
    std::vector<b2Body*> bodies_;
};

std::unique_ptr<PeerWorld> make(const PeerScene& scene, double frame_step) {
    return std::make_unique<Box2dWorld>(scene, frame_step);
}

}  // namespace

PeerEngine box2d_peer() { return {"Box2D " WORKBOOK_BOX2D_VERSION, &make}; }

}  // namespace workbook::accuracy
