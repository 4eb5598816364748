#pragma once
/// \file
/// The peer engines on the accuracy bench's axes: Chipmunk 7, Box2D 2.4 and Bullet 3, from
/// Debian's packages (libchipmunk-dev, libbox2d-dev, libbullet-dev; `./workbook bench
/// accuracy` installs them the way `bench speed` does). Each that the build found runs the
/// families that only need balls, boxes and a ground line, set up the same way, at the same
/// frame steps, and is measured by the same closed forms (families.hpp).
///
/// Every peer gets what its manual asks for such scenes and nothing else: no sleeping,
/// restitution e and friction mu for every contact (mu = 0 but in the friction families), no
/// restitution threshold (Box2D and Bullet stop bounces slower than 1 m/s and 0.2 m/s by
/// default, which would end the bouncing ball early), one engine step per frame with the
/// engine's default iterations; their friction is otherwise on its defaults. Chipmunk and
/// Box2D are 2D and Box2D computes in single precision, as does Debian's Bullet; the bodies
/// move in the x-y plane and turn about z.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "bench.hpp"

namespace workbook::accuracy {

/// A ball of a peer scene, in the x-y plane. A solid sphere: the 2D peers, whose circles are
/// discs (I = m r^2 / 2), are given its moment of inertia 2/5 m r^2, so that a ball that rolls
/// rolls as the workbook's (nothing turns a ball in the frictionless families).
struct PeerBall {
    double mass = 1.0, radius = 0.1;
    double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
};

/// A box of a peer scene, axis-aligned at the start, in the x-y plane (Bullet's is
/// 2 half_depth deep; the 2D peers' moment of inertia is a box's about z, m (w^2 + h^2) / 12).
struct PeerBox {
    double mass = 1.0, half_width = 0.1, half_height = 0.05, half_depth = 0.05;
    double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
};

/// What a peer builds: balls, then boxes (body indices in that order), optionally the ground
/// line y = 0 (solid below), gravity (gx, -g), one coefficient of restitution and one of
/// friction for every contact. Each engine mixes two bodies' coefficients its own way
/// (restitution: Chipmunk and Bullet multiply, Box2D takes the larger; friction: Chipmunk and
/// Bullet multiply, Box2D takes the square root of the product), so each peer sets what gives
/// these values for every pair. The peers have one friction coefficient, static and dynamic.
struct PeerScene {
    std::vector<PeerBall> balls;
    std::vector<PeerBox> boxes;
    bool ground = false;
    double g = 0.0;
    double gx = 0.0;  ///< gravity along x, m/s^2 (the incline, seen in its own frame)
    double restitution = 1.0;
    double friction = 0.0;
};

/// A body's state as a peer reports it.
struct PeerState {
    double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
    double spin = 0.0;  ///< angular velocity about z, rad/s
};

/// One peer world, stepped a fixed frame step at a time.
class PeerWorld {
public:
    virtual ~PeerWorld() = default;
    virtual void step() = 0;
    /// Body `index`: the balls first, then the boxes, in the scene's order.
    [[nodiscard]] virtual PeerState body(std::size_t index) const = 0;
};

/// A peer engine the build found.
struct PeerEngine {
    std::string name;  ///< with its version, as on figures: "Box2D 2.4.1"
    std::unique_ptr<PeerWorld> (*make)(const PeerScene& scene, double frame_step);
};

/// Every peer compiled in (none when the packages were missing at configure time).
std::vector<PeerEngine> peer_engines();

/// The families the peers run: bouncing-ball, head-on, cradle, incline and thrown-ball.
bool peers_run(const std::string& family_id);

/// One run of a family the peers run (peers_run()) in `engine` at `frame_step`.
FamilyError peer_family_error(const std::string& family_id, const PeerEngine& engine, double frame_step);

/// The peers' points for one family at every frame rate of the sweep (frame_rates()).
std::vector<BenchPoint> peer_points(const std::string& family_id);

// Each engine, defined in peer_<engine>.cpp when the build found it.
PeerEngine chipmunk_peer();
PeerEngine box2d_peer();
PeerEngine bullet_peer();

}  // namespace workbook::accuracy
