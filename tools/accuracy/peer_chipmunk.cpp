// Chipmunk 7 on the accuracy bench (peers.hpp).
#include <chipmunk/chipmunk.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "peers.hpp"

namespace workbook::accuracy {

namespace {

class ChipmunkWorld final : public PeerWorld {
public:
    ChipmunkWorld(const PeerScene& scene, double frame_step) : space_(cpSpaceNew()), dt_(frame_step) {
        cpSpaceSetGravity(space_, cpv(scene.gx, -scene.g));
        // Chipmunk's default slop, 0.1, is meant for pixels; the balls here have radii of 0.1 and 0.5 m.
        cpSpaceSetCollisionSlop(space_, 1e-3);
        cpSpaceSetSleepTimeThreshold(space_, std::numeric_limits<cpFloat>::infinity());
        // Chipmunk multiplies two shapes' elasticities and two shapes' frictions: the square
        // roots on every shape give e and mu.
        const double elasticity = std::sqrt(scene.restitution), friction = std::sqrt(scene.friction);
        for (const PeerBall& b : scene.balls) {
            // A solid sphere's moment, 2/5 m r^2, not a disc's (peers.hpp).
            cpBody* body = cpSpaceAddBody(space_, cpBodyNew(b.mass, 0.4 * b.mass * b.radius * b.radius));
            cpBodySetPosition(body, cpv(b.x, b.y));
            cpBodySetVelocity(body, cpv(b.vx, b.vy));
            add_shape(cpCircleShapeNew(body, b.radius, cpvzero), elasticity, friction);
            bodies_.push_back(body);
        }
        for (const PeerBox& b : scene.boxes) {
            const double w = 2.0 * b.half_width, h = 2.0 * b.half_height;
            cpBody* body = cpSpaceAddBody(space_, cpBodyNew(b.mass, cpMomentForBox(b.mass, w, h)));
            cpBodySetPosition(body, cpv(b.x, b.y));
            cpBodySetVelocity(body, cpv(b.vx, b.vy));
            add_shape(cpBoxShapeNew(body, w, h, 0.0), elasticity, friction);
            bodies_.push_back(body);
        }
        if (scene.ground) {
            // A thick segment (radius 1 m) whose top face is the line y = 0.
            add_shape(cpSegmentShapeNew(cpSpaceGetStaticBody(space_), cpv(-100.0, -1.0), cpv(100.0, -1.0), 1.0), elasticity,
                      friction);
        }
    }
    ChipmunkWorld(const ChipmunkWorld&) = delete;
    ChipmunkWorld& operator=(const ChipmunkWorld&) = delete;
    ~ChipmunkWorld() override {
        for (cpShape* shape : shapes_) {
            cpSpaceRemoveShape(space_, shape);
            cpShapeFree(shape);
        }
        for (cpBody* body : bodies_) {
            cpSpaceRemoveBody(space_, body);
            cpBodyFree(body);
        }
        cpSpaceFree(space_);
    }
    void step() override { cpSpaceStep(space_, dt_); }
    [[nodiscard]] PeerState body(std::size_t index) const override {
        const cpVect p = cpBodyGetPosition(bodies_[index]);
        const cpVect v = cpBodyGetVelocity(bodies_[index]);
        return {p.x, p.y, v.x, v.y, cpBodyGetAngularVelocity(bodies_[index])};
    }

private:
    void add_shape(cpShape* shape, double elasticity, double friction) {
        cpShapeSetElasticity(shape, elasticity);
        cpShapeSetFriction(shape, friction);
        shapes_.push_back(cpSpaceAddShape(space_, shape));
    }
    cpSpace* space_;
    double dt_;
    std::vector<cpBody*> bodies_;
    std::vector<cpShape*> shapes_;
};

std::unique_ptr<PeerWorld> make(const PeerScene& scene, double frame_step) {
    return std::make_unique<ChipmunkWorld>(scene, frame_step);
}

}  // namespace

PeerEngine chipmunk_peer() { return {std::string("Chipmunk ") + cpVersionString, &make}; }

}  // namespace workbook::accuracy
