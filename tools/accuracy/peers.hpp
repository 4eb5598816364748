#pragma once
/// \file
/// The peer engines on the accuracy bench's axes: Chipmunk 7, Box2D 2.4 and Bullet 3, from
/// Debian's packages (libchipmunk-dev, libbox2d-dev, libbullet-dev; `./workbook bench
/// accuracy` installs them the way `bench speed` does). Each that the build found runs the
/// families that only need balls and a ground line, set up the same way, at the same frame
/// steps, and is measured by the same closed forms (families.hpp).
///
/// Every peer gets what its manual asks for such scenes and nothing else: no friction, no
/// sleeping, restitution e for every contact (each engine mixes two bodies' coefficients its
/// own way: Chipmunk and Bullet multiply them, Box2D takes the larger), no restitution
/// threshold (Box2D and Bullet stop bounces slower than 1 m/s and 0.2 m/s by default, which
/// would end the bouncing ball early), one engine step per frame with the engine's default
/// iterations. Chipmunk and Box2D are 2D and Box2D computes in single precision, as does
/// Debian's Bullet; the balls move in the x-y plane.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "bench.hpp"

namespace workbook::accuracy {

/// A ball of a peer scene, in the x-y plane.
struct PeerBall {
    double mass = 1.0, radius = 0.1;
    double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
};

/// What a peer builds: balls, optionally the ground line y = 0 (solid below), gravity -g along y,
/// and one coefficient of restitution for every contact.
struct PeerScene {
    std::vector<PeerBall> balls;
    bool ground = false;
    double g = 0.0;
    double restitution = 1.0;
};

/// A ball's state as a peer reports it.
struct PeerState {
    double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
};

/// One peer world, stepped a fixed frame step at a time.
class PeerWorld {
public:
    virtual ~PeerWorld() = default;
    virtual void step() = 0;
    [[nodiscard]] virtual PeerState ball(std::size_t index) const = 0;
};

/// A peer engine the build found.
struct PeerEngine {
    std::string name;  ///< with its version, as on figures: "Box2D 2.4.1"
    std::unique_ptr<PeerWorld> (*make)(const PeerScene& scene, double frame_step);
};

/// Every peer compiled in (none when the packages were missing at configure time).
std::vector<PeerEngine> peer_engines();

/// The families the peers run: bouncing-ball, head-on and cradle.
bool peers_run(const std::string& family_id);

/// The peers' points for one family at every frame rate of the sweep (frame_rates()).
std::vector<BenchPoint> peer_points(const std::string& family_id);

// Each engine, defined in peer_<engine>.cpp when the build found it.
PeerEngine chipmunk_peer();
PeerEngine box2d_peer();
PeerEngine bullet_peer();

}  // namespace workbook::accuracy
