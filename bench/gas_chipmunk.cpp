// The gas in Chipmunk 7 (Debian's libchipmunk-dev), with its default settings: bounding-box
// tree broad phase, 10 solver iterations, sleeping off.
#include <chipmunk/chipmunk.h>

#include <ctime>
#include <vector>

#include "gas.hpp"

namespace workbook::bench {

GasResult run_chipmunk(const Gas& gas, int steps) {
    cpSpace* space = cpSpaceNew();
    cpSpaceSetGravity(space, cpvzero);
    std::vector<cpBody*> bodies;
    std::vector<cpShape*> shapes;
    bodies.reserve(gas.discs.size());
    const cpFloat moment = cpMomentForCircle(Gas::mass, 0, Gas::radius, cpvzero);
    for (const Disc& d : gas.discs) {
        cpBody* body = cpSpaceAddBody(space, cpBodyNew(Gas::mass, moment));
        cpBodySetPosition(body, cpv(d.x, d.y));
        cpBodySetVelocity(body, cpv(d.vx, d.vy));
        cpShape* shape = cpSpaceAddShape(space, cpCircleShapeNew(body, Gas::radius, cpvzero));
        cpShapeSetElasticity(shape, 1.0);
        cpShapeSetFriction(shape, 0.0);
        bodies.push_back(body);
        shapes.push_back(shape);
    }
    // Thick walls (segments of radius 1 m whose inner faces lie on the box): thin segments
    // let fast discs squeeze through in a 1/60 s step.
    const double thickness = 1.0;
    const double h = gas.side / 2 + thickness;
    const cpVect corners[4] = {cpv(-h, -h), cpv(h, -h), cpv(h, h), cpv(-h, h)};
    for (int i = 0; i < 4; ++i) {
        cpShape* wall = cpSpaceAddShape(space, cpSegmentShapeNew(cpSpaceGetStaticBody(space), corners[i], corners[(i + 1) % 4], thickness));
        cpShapeSetElasticity(wall, 1.0);
        cpShapeSetFriction(wall, 0.0);
        shapes.push_back(wall);
    }
    auto energy = [&bodies] {
        double sum = 0.0;
        for (cpBody* body : bodies) sum += cpvlengthsq(cpBodyGetVelocity(body));
        return kinetic(sum);
    };
    GasResult result;
    result.energy_before = energy();
    const std::clock_t start = std::clock();
    for (int i = 0; i < steps; ++i) cpSpaceStep(space, Gas::time_step);
    result.seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    result.energy_after = energy();
    for (cpBody* body : bodies) {
        const cpVect p = cpBodyGetPosition(body);
        if (!inside(gas, p.x, p.y)) ++result.escaped;
    }
    for (cpShape* shape : shapes) {
        cpSpaceRemoveShape(space, shape);
        cpShapeFree(shape);
    }
    for (cpBody* body : bodies) {
        cpSpaceRemoveBody(space, body);
        cpBodyFree(body);
    }
    cpSpaceFree(space);
    return result;
}

}  // namespace workbook::bench
