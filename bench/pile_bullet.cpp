// The pile (pile.hpp) in Bullet 3.24 (Debian's libbullet-dev, single precision), on its
// defaults: dynamic AABB tree broad phase, sequential impulse solver with 10 iterations and
// split impulse, deactivation (sleeping) on, one fixed substep per step. Set here: no friction,
// e = 0, and the plane: spheres held in z = 0 by a linear factor (1, 1, 0) and no rotation;
// the ground and walls are static planes.
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "pile.hpp"

namespace workbook::bench {

PileResult run_pile_bullet(const Pile& pile, int steps, double budget) {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, static_cast<btScalar>(-Pile::gravity), 0));

    btSphereShape sphere(static_cast<btScalar>(Pile::radius));
    btVector3 inertia(0, 0, 0);
    sphere.calculateLocalInertia(static_cast<btScalar>(Pile::mass), inertia);
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    for (std::size_t i = 0; i < pile.x.size(); ++i) {
        btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(Pile::mass), nullptr, &sphere, inertia);
        info.m_startWorldTransform.setOrigin(btVector3(static_cast<btScalar>(pile.x[i]), static_cast<btScalar>(pile.y[i]), 0));
        info.m_restitution = 0;
        info.m_friction = 0;
        auto body = std::make_unique<btRigidBody>(info);
        body->setLinearFactor(btVector3(1, 1, 0));
        body->setAngularFactor(0);
        world.addRigidBody(body.get());
        bodies.push_back(std::move(body));
    }
    const auto h = static_cast<btScalar>(pile.width / 2);
    // The planes n . x = c: the ground y = 0 and the walls x = -w/2 and x = w/2, each facing in.
    const std::pair<btVector3, btScalar> planes[3] = {{btVector3(0, 1, 0), 0}, {btVector3(1, 0, 0), -h}, {btVector3(-1, 0, 0), -h}};
    std::vector<std::unique_ptr<btStaticPlaneShape>> wall_shapes;
    std::vector<std::unique_ptr<btRigidBody>> walls;
    for (const auto& [normal, constant] : planes) {
        wall_shapes.push_back(std::make_unique<btStaticPlaneShape>(normal, constant));
        btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, wall_shapes.back().get());
        info.m_restitution = 0;
        info.m_friction = 0;
        walls.push_back(std::make_unique<btRigidBody>(info));
        world.addRigidBody(walls.back().get());
    }
    const auto dt = static_cast<btScalar>(Pile::time_step);
    const double seconds = timed_steps(steps, budget, [&world, dt] { world.stepSimulation(dt, 1, dt); });
    std::vector<double> x, y, vx, vy;
    for (const auto& body : bodies) {
        const btVector3& p = body->getWorldTransform().getOrigin();
        const btVector3& v = body->getLinearVelocity();
        x.push_back(static_cast<double>(p.x()));
        y.push_back(static_cast<double>(p.y()));
        vx.push_back(static_cast<double>(v.x()));
        vy.push_back(static_cast<double>(v.y()));
    }
    for (const auto& body : bodies) world.removeRigidBody(body.get());
    for (const auto& wall : walls) world.removeRigidBody(wall.get());
    return finish_pile(pile, seconds, x, y, vx, vy);
}

}  // namespace workbook::bench
