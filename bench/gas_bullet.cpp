// The gas in Bullet 3.24 (Debian's libbullet-dev, single precision): spheres held in the
// plane z = 0 by a linear factor (1, 1, 0) and no rotation, walls as static planes, the
// dynamic AABB tree broad phase, sleeping off, one fixed substep per step.
#include <btBulletDynamicsCommon.h>

#include <ctime>
#include <memory>
#include <vector>

#include "gas.hpp"

namespace workbook::bench {

GasResult run_bullet(const Gas& gas, int steps) {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, 0, 0));

    btSphereShape sphere(static_cast<btScalar>(Gas::radius));
    btVector3 inertia(0, 0, 0);
    sphere.calculateLocalInertia(static_cast<btScalar>(Gas::mass), inertia);
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    bodies.reserve(gas.discs.size());
    for (const Disc& d : gas.discs) {
        btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(Gas::mass), nullptr, &sphere, inertia);
        info.m_startWorldTransform.setOrigin(btVector3(static_cast<btScalar>(d.x), static_cast<btScalar>(d.y), 0));
        info.m_restitution = 1;
        info.m_friction = 0;
        auto body = std::make_unique<btRigidBody>(info);
        body->setLinearVelocity(btVector3(static_cast<btScalar>(d.vx), static_cast<btScalar>(d.vy), 0));
        body->setLinearFactor(btVector3(1, 1, 0));
        body->setAngularFactor(0);
        body->setActivationState(DISABLE_DEACTIVATION);
        world.addRigidBody(body.get());
        bodies.push_back(std::move(body));
    }
    const auto h = static_cast<btScalar>(gas.side / 2);
    const btVector3 normals[4] = {btVector3(1, 0, 0), btVector3(-1, 0, 0), btVector3(0, 1, 0), btVector3(0, -1, 0)};
    std::vector<std::unique_ptr<btStaticPlaneShape>> wall_shapes;
    std::vector<std::unique_ptr<btRigidBody>> walls;
    for (const btVector3& n : normals) {
        // The plane n . x = -h: each wall faces the centre.
        wall_shapes.push_back(std::make_unique<btStaticPlaneShape>(n, -h));
        btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, wall_shapes.back().get());
        info.m_restitution = 1;
        info.m_friction = 0;
        walls.push_back(std::make_unique<btRigidBody>(info));
        world.addRigidBody(walls.back().get());
    }
    auto energy = [&bodies] {
        double sum = 0.0;
        for (const auto& body : bodies) sum += static_cast<double>(body->getLinearVelocity().length2());
        return kinetic(sum);
    };
    GasResult result;
    result.energy_before = energy();
    const auto dt = static_cast<btScalar>(Gas::time_step);
    const std::clock_t start = std::clock();
    for (int i = 0; i < steps; ++i) world.stepSimulation(dt, 1, dt);
    result.seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    result.energy_after = energy();
    for (const auto& body : bodies) {
        const btVector3& p = body->getWorldTransform().getOrigin();
        if (!inside(gas, static_cast<double>(p.x()), static_cast<double>(p.y()))) ++result.escaped;
    }
    for (const auto& body : bodies) world.removeRigidBody(body.get());
    for (const auto& wall : walls) world.removeRigidBody(wall.get());
    return result;
}

}  // namespace workbook::bench
