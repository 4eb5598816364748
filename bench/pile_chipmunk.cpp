// The pile (pile.hpp) in Chipmunk 7 (Debian's libchipmunk-dev), on its defaults: bounding-box
// tree broad phase, 10 solver iterations, sleeping off, collision bias (the share of an overlap
// left after a second) 0.1^60. Set here: no friction, e = 0, and the collision slop, the
// overlap Chipmunk lets stand, which defaults to 0.1 because its manual counts in pixels: in
// metres that is a whole diameter of these discs, so it gets the workbook's slop, 2 mm.
#include <chipmunk/chipmunk.h>

#include <vector>

#include "pile.hpp"

namespace workbook::bench {

PileResult run_pile_chipmunk(const Pile& pile, int steps, double budget) {
    cpSpace* space = cpSpaceNew();
    cpSpaceSetGravity(space, cpv(0, -Pile::gravity));
    cpSpaceSetCollisionSlop(space, PileKnobs{}.slop);
    std::vector<cpBody*> bodies;
    std::vector<cpShape*> shapes;
    const cpFloat moment = cpMomentForCircle(Pile::mass, 0, Pile::radius, cpvzero);
    for (std::size_t i = 0; i < pile.x.size(); ++i) {
        cpBody* body = cpSpaceAddBody(space, cpBodyNew(Pile::mass, moment));
        cpBodySetPosition(body, cpv(pile.x[i], pile.y[i]));
        cpShape* shape = cpSpaceAddShape(space, cpCircleShapeNew(body, Pile::radius, cpvzero));
        cpShapeSetElasticity(shape, 0.0);
        cpShapeSetFriction(shape, 0.0);
        bodies.push_back(body);
        shapes.push_back(shape);
    }
    // Thick segments (radius 1 m) whose inner faces are the ground y = 0 and the walls x = +-w/2:
    // a thin one would let a disc pushed hard by the pile squeeze through.
    const double thickness = 1.0, h = pile.width / 2 + thickness, top = pile.wall_height();
    const cpVect ends[3][2] = {{cpv(-h, -thickness), cpv(h, -thickness)}, {cpv(-h, -thickness), cpv(-h, top)},
                               {cpv(h, -thickness), cpv(h, top)}};
    for (const auto& end : ends) {
        cpShape* wall = cpSpaceAddShape(space, cpSegmentShapeNew(cpSpaceGetStaticBody(space), end[0], end[1], thickness));
        cpShapeSetElasticity(wall, 0.0);
        cpShapeSetFriction(wall, 0.0);
        shapes.push_back(wall);
    }
    const double seconds = timed_steps(steps, budget, [space] { cpSpaceStep(space, Pile::time_step); });
    std::vector<double> x, y, vx, vy;
    for (cpBody* body : bodies) {
        const cpVect p = cpBodyGetPosition(body), v = cpBodyGetVelocity(body);
        x.push_back(p.x);
        y.push_back(p.y);
        vx.push_back(v.x);
        vy.push_back(v.y);
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
    return finish_pile(pile, seconds, x, y, vx, vy);
}

}  // namespace workbook::bench
