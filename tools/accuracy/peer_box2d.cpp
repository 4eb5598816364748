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
        : world_(b2Vec2(0.0f, static_cast<float>(-scene.g))), dt_(static_cast<float>(frame_step)) {
        world_.SetAllowSleeping(false);
        // Box2D takes the larger of two fixtures' restitutions: e on every fixture gives e. Its
        // threshold (default 1 m/s, below which it does not bounce) is off.
        b2FixtureDef fixture;
        fixture.friction = 0.0f;
        fixture.restitution = static_cast<float>(scene.restitution);
        fixture.restitutionThreshold = 0.0f;
        for (const PeerBall& b : scene.balls) {
            b2BodyDef def;
            def.type = b2_dynamicBody;
            def.position.Set(static_cast<float>(b.x), static_cast<float>(b.y));
            def.linearVelocity.Set(static_cast<float>(b.vx), static_cast<float>(b.vy));
            def.allowSleep = false;
            b2Body* body = world_.CreateBody(&def);
            b2CircleShape circle;
            circle.m_radius = static_cast<float>(b.radius);
            fixture.shape = &circle;
            fixture.density = static_cast<float>(b.mass / (std::numbers::pi * b.radius * b.radius));
            body->CreateFixture(&fixture);
            bodies_.push_back(body);
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
    [[nodiscard]] PeerState ball(std::size_t index) const override {
        const b2Vec2 p = bodies_[index]->GetPosition();
        const b2Vec2 v = bodies_[index]->GetLinearVelocity();
        return {static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(v.x), static_cast<double>(v.y)};
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
