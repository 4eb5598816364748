// Bullet 3 on the accuracy bench (peers.hpp). Debian's Bullet computes in single precision.
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "peers.hpp"

namespace workbook::accuracy {

namespace {

class BulletWorld final : public PeerWorld {
public:
    BulletWorld(const PeerScene& scene, double frame_step)
        : dispatcher_(&configuration_),
          world_(&dispatcher_, &broadphase_, &solver_, &configuration_),
          dt_(static_cast<btScalar>(frame_step)) {
        world_.setGravity(btVector3(static_cast<btScalar>(scene.gx), static_cast<btScalar>(-scene.g), 0));
        // Bullet gives no restitution below 0.2 m/s of approach by default; off.
        world_.getSolverInfo().m_restitutionVelocityThreshold = 0;
        // Bullet multiplies two bodies' restitutions and two bodies' frictions: the square roots
        // on every body give e and mu.
        const auto restitution = static_cast<btScalar>(std::sqrt(scene.restitution));
        const auto friction = static_cast<btScalar>(std::sqrt(scene.friction));
        auto add_body = [&](btCollisionShape* shape, double mass, double x, double y, double vx, double vy) {
            btVector3 inertia(0, 0, 0);
            shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
            btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass), nullptr, shape, inertia);
            info.m_startWorldTransform.setIdentity();
            info.m_startWorldTransform.setOrigin(btVector3(static_cast<btScalar>(x), static_cast<btScalar>(y), 0));
            info.m_restitution = restitution;
            info.m_friction = friction;
            auto& body = bodies_.emplace_back(std::make_unique<btRigidBody>(info));
            body->setLinearVelocity(btVector3(static_cast<btScalar>(vx), static_cast<btScalar>(vy), 0));
            body->setLinearFactor(btVector3(1, 1, 0));   // the x-y plane, as the 2D peers,
            body->setAngularFactor(btVector3(0, 0, 1));  // turning about z alone
            body->setActivationState(DISABLE_DEACTIVATION);
            world_.addRigidBody(body.get());
        };
        for (const PeerBall& b : scene.balls) {
            auto& shape = shapes_.emplace_back(std::make_unique<btSphereShape>(static_cast<btScalar>(b.radius)));
            add_body(shape.get(), b.mass, b.x, b.y, b.vx, b.vy);
        }
        for (const PeerBox& b : scene.boxes) {
            auto& shape = shapes_.emplace_back(std::make_unique<btBoxShape>(
                btVector3(static_cast<btScalar>(b.half_width), static_cast<btScalar>(b.half_height), static_cast<btScalar>(b.half_depth))));
            add_body(shape.get(), b.mass, b.x, b.y, b.vx, b.vy);
        }
        if (scene.ground) {
            ground_shape_ = std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0);
            btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, ground_shape_.get());
            info.m_restitution = restitution;
            info.m_friction = friction;
            ground_ = std::make_unique<btRigidBody>(info);
            world_.addRigidBody(ground_.get());
        }
    }
    BulletWorld(const BulletWorld&) = delete;
    BulletWorld& operator=(const BulletWorld&) = delete;
    ~BulletWorld() override {
        for (const auto& body : bodies_) world_.removeRigidBody(body.get());
        if (ground_) world_.removeRigidBody(ground_.get());
    }
    // One engine step of exactly the frame step (Bullet's own substepping off).
    void step() override { world_.stepSimulation(dt_, 1, dt_); }
    [[nodiscard]] PeerState body(std::size_t index) const override {
        const btVector3& p = bodies_[index]->getWorldTransform().getOrigin();
        const btVector3& v = bodies_[index]->getLinearVelocity();
        return {static_cast<double>(p.x()), static_cast<double>(p.y()), static_cast<double>(v.x()),
                static_cast<double>(v.y()), static_cast<double>(bodies_[index]->getAngularVelocity().z())};
    }

private:
    btDefaultCollisionConfiguration configuration_;
    btCollisionDispatcher dispatcher_;
    btDbvtBroadphase broadphase_;
    btSequentialImpulseConstraintSolver solver_;
    btDiscreteDynamicsWorld world_;
    btScalar dt_;
    std::vector<std::unique_ptr<btConvexInternalShape>> shapes_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;
    std::unique_ptr<btStaticPlaneShape> ground_shape_;
    std::unique_ptr<btRigidBody> ground_;
};

std::unique_ptr<PeerWorld> make(const PeerScene& scene, double frame_step) {
    return std::make_unique<BulletWorld>(scene, frame_step);
}

}  // namespace

PeerEngine bullet_peer() {
    const int version = btGetVersion();
    return {"Bullet " + std::to_string(version / 100) + "." + std::to_string(version % 100), &make};
}

}  // namespace workbook::accuracy
