#pragma once
/// \file
/// The broad phase: which pairs of bodies are worth handing to the narrow phase, and which
/// are worth tracing along their paths (the swept test of swept_spheres.hpp).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "workbook/rigid_body.hpp"
#include "workbook/swept_spheres.hpp"
#include "workbook/vector3.hpp"

namespace workbook {

/// Radius of a sphere around the body's position that holds its whole shape; infinite for a plane.
double bounding_radius(const RigidBody& body);

/// Two body indices, `first < second`.
struct BodyPair {
    std::uint32_t first;   ///< the smaller index
    std::uint32_t second;  ///< the larger index
};

/// One body as the broad phase reads it: 72 bytes instead of a whole RigidBody (328), so
/// that the grid's passes stream through contiguous memory. Kept in body order, planes too.
/// (Outside BroadPhase so that the API reference has no private nested class.)
struct GridProxy {
    double x = 0.0;             ///< centre, x, m
    double y = 0.0;             ///< centre, y, m
    double z = 0.0;             ///< centre, z, m
    double radius = 0.0;        ///< bounding radius, m (workbook::bounding_radius; unused for a plane)
    double travel = 0.0;        ///< how far a swept sphere or a box moved this step, m; 0 for every other body
    Vector3 start{};            ///< with a swept set: where the body started the step, m (next to its end,
                                ///< so that the swept test reads both from one place)
    std::uint32_t index = 0;    ///< body index
    bool movable = false;       ///< false for an immovable body
    bool plane = false;         ///< a plane: unbounded, never in the grid
    bool sphere = false;        ///< a sphere: the only shape the swept test traces
    bool fast = false;          ///< a sphere the swept test traces (set by the broad phase on its copies)
};

/// A bounded proxy as the grid keeps it for a set without the swept test: what the overlap
/// test, the planes' test and BroadPhase::bodies_near() read of it, 40 bytes where a GridProxy
/// is 72 (the swept test's travel and start, and its flags, left out). Event timing's grid of
/// widened spheres is walked over these: at N = 100,000 the walk reads every copy from memory.
struct CellProxy {
    double x = 0.0;           ///< centre, x, m
    double y = 0.0;           ///< centre, y, m
    double z = 0.0;           ///< centre, z, m
    double radius = 0.0;      ///< bounding radius, m
    std::uint32_t index = 0;  ///< body index
    bool movable = false;     ///< false for an immovable body
    bool plane = false;       ///< a plane, in a compact set's list (ProxySet::cells); never in the grid
};

/// A plane as the broad phase reads it.
struct PlaneProxy {
    std::uint32_t index;  ///< body index
    bool movable;         ///< false for an immovable plane
    Vector3 point;        ///< the body's position, m
    Vector3 normal;       ///< unit normal in the world frame
};

/// Orders plane proxies by body index, for std::lower_bound over ProxySet::planes (the
/// iterator algorithm: libc++ 14, the oldest Xcode's, has no std::ranges algorithms).
inline bool plane_before(const PlaneProxy& plane, std::uint32_t index) { return plane.index < index; }

/// The body proxies of one step, in body order, and what the broad phase should look for.
struct ProxySet {
    std::vector<GridProxy> proxies;   ///< every body, in body order (empty for a compact set)
    /// For a compact set: every body, in body order, as the 40-byte copies the grid of a set
    /// without the swept test keeps (CellProxy), rather than as 72-byte GridProxy copies whose
    /// travel, start and flags only the swept test reads. Event timing gathers every body so
    /// at the start of each step: at N = 100,000 the larger copies were 7 MB written and read
    /// twice more by the grid, every step, from memory.
    std::vector<CellProxy> cells;
    bool compact = false;             ///< the bodies are in `cells`, not `proxies` (set by clear())
    std::vector<PlaneProxy> planes;   ///< the planes again, in body order, with their normals
    /// Also find the pairs the swept test must try: pairs with a fast sphere (travel greater than
    /// `fast_travel`) whose paths may come within touching distance.
    bool swept = false;
    double fast_travel = 0.0;         ///< m; the smallest sphere radius in the world
    /// Without a swept set: cells half as wide, each walked against the cells two around it
    /// rather than one. Fewer pairs to test where a few large spheres set the cell width (event
    /// timing's widened spheres in a pile), more cells to visit where they are sparse.
    bool fine_cells = false;
    /// Also pair bodies whose bounding spheres are apart by less than this, m (speculative
    /// contacts, ContactSolverSettings::speculative_distance; 0 for none). Set after gathering.
    double margin = 0.0;
    // Gathered by add() on the way, so that the grid needs no pass of its own to find them:
    Vector3 low{};                    ///< smallest coordinates of a bounded body's centre, m
    Vector3 high{};                   ///< largest, m
    double largest_radius = 0.0;      ///< largest bounding radius of a bounded body, m
    double poison = 0.0;              ///< 0 when every centre and radius is finite, NaN otherwise
    std::size_t bounded = 0;          ///< bodies other than planes
    double travel_sum = 0.0;          ///< sum over spheres of min(travel, 4 radii), m
    std::size_t spheres = 0;          ///< spheres

    /// Starts a new gathering for `count` bodies; a `compact_copies` set keeps them in `cells`
    /// and can have no swept test.
    void clear(std::size_t count, bool compact_copies = false) {
        proxies.clear();
        cells.clear();
        compact = compact_copies;
        if (compact && cells.capacity() < count) cells.reserve(count);
        if (!compact && proxies.capacity() < count) proxies.reserve(count);
        planes.clear();
        swept = false;
        fine_cells = false;
        margin = 0.0;
        constexpr double inf = std::numeric_limits<double>::infinity();
        low = {inf, inf, inf};
        high = {-inf, -inf, -inf};
        largest_radius = 0.0;
        poison = 0.0;
        bounded = 0;
        travel_sum = 0.0;
        spheres = 0;
    }

    /// How many bodies have been gathered.
    [[nodiscard]] std::size_t size() const { return compact ? cells.size() : proxies.size(); }

    /// Appends body `index` (the next one in body order), with the travel and start of a swept
    /// sphere; `inflate` widens its bounding sphere (event timing's reach over a step).
    void add(const RigidBody& body, std::uint32_t index, double travel = 0.0, const Vector3& start = {},
             double inflate = 0.0) {
        if (body.shape.kind == ShapeKind::plane) {
            add_plane(body, index);
            return;
        }
        if (compact) {
            add_compact(body, index, inflate);
            return;
        }
        GridProxy p;
        p.x = body.position.x;
        p.y = body.position.y;
        p.z = body.position.z;
        p.sphere = body.shape.kind == ShapeKind::sphere;
        p.radius = (p.sphere ? body.shape.radius : bounding_radius(body)) + inflate;
        p.travel = travel;
        p.start = start;
        p.index = index;
        p.movable = !body.is_immovable();
        proxies.push_back(p);
        ++bounded;
        if (p.sphere) {
            ++spheres;
            travel_sum += std::min(travel, 4.0 * p.radius);  // (NaN counts as 0)
        }
        // x * 0 is 0 for every finite x and NaN otherwise: one sum says whether all are finite.
        poison += (p.x + p.y + p.z + p.radius) * 0.0;
        low.x = std::min(low.x, p.x), low.y = std::min(low.y, p.y), low.z = std::min(low.z, p.z);
        high.x = std::max(high.x, p.x), high.y = std::max(high.y, p.y), high.z = std::max(high.z, p.z);
        largest_radius = std::max(largest_radius, p.radius);
    }

    /// Appends to a compact set body `index` (the next one in body order), a body that is not a
    /// plane, from what the caller knows of it: its centre, its bounding radius already widened,
    /// whether it is movable and whether it is a sphere. The same numbers add() keeps, for a
    /// caller that holds them and need not read the body for them (event timing's first pass).
    void add_compact(const Vector3& centre, double radius, std::uint32_t index, bool movable, bool sphere) {
        CellProxy& p = cells.emplace_back();
        p.x = centre.x;
        p.y = centre.y;
        p.z = centre.z;
        p.radius = radius;
        p.index = index;
        p.movable = movable;
        ++bounded;
        if (sphere) ++spheres;  // (a compact set has no travel to sum)
        poison += (p.x + p.y + p.z + p.radius) * 0.0;
        low.x = std::min(low.x, p.x), low.y = std::min(low.y, p.y), low.z = std::min(low.z, p.z);
        high.x = std::max(high.x, p.x), high.y = std::max(high.y, p.y), high.z = std::max(high.z, p.z);
        largest_radius = std::max(largest_radius, p.radius);
    }

private:
    void add_plane(const RigidBody& body, std::uint32_t index);

    /// add() for a compact set: the same numbers, kept as a CellProxy.
    void add_compact(const RigidBody& body, std::uint32_t index, double inflate) {
        const bool sphere = body.shape.kind == ShapeKind::sphere;
        add_compact(body.position, (sphere ? body.shape.radius : bounding_radius(body)) + inflate, index,
                    !body.is_immovable(), sphere);
    }
};

/// A uniform grid over the bodies' bounding spheres, rebuilt every step.
///
/// Why a grid and not sort-and-sweep: for the even densities the workbook's scenes have (a
/// gas, a pile, a few bodies) a grid whose cells are one diameter wide finds each body's
/// neighbours in the 3 x 3 x 3 cells around it, a constant amount of work per body, so the
/// whole pass is linear in N. Sort-and-sweep along one axis finds every body whose extent
/// overlaps along that axis: in the 2D gas of the speed bench (bench/gas.hpp) that is a strip through the whole box,
/// about N * 2 d / L bodies, so its cost grows as N^1.5 (measured with bench/stages.cpp:
/// at N = 100,000 the strip holds about 100 bodies against the grid's 0.5 per cell).
///
/// The grid is walked cell by cell, each cell against itself and the half of its neighbours
/// that come after it, so that each pair is met once and memory is read in order; the pairs
/// are then sorted by (first, second), the order in which testing every pair visits them, so
/// that sequential responders see contacts in the same order and the results are
/// bit-identical to testing all pairs. Planes are unbounded and stay out of the grid: each
/// body is paired with each plane its bounding sphere reaches, visiting only the cells near it.
///
/// With a swept set the same walk finds the swept test's candidates: two spheres' paths can
/// meet only if their ends lie within r_1 + t_1 + r_2 + t_2 (t the distance travelled). Cells
/// are sized for the largest radius plus twice the mean travel, not for the fastest sphere,
/// whose speed grows with N; a sphere reaching further ("large") searches the cells beyond
/// its neighbours itself, and one that travelled more than four of the largest radii ("wide")
/// searches as far as it reaches without widening anyone else's search.
class BroadPhase {
public:
    /// Finds, for the gathered `set`, every pair whose bounding spheres overlap (a conservative
    /// test: the narrow phase decides), plus every body-plane pair whose sphere reaches the
    /// plane (both within `set.margin`), leaving out pairs of two immovable bodies unless `immovable_pairs`; sorted. With
    /// `set.swept`, also the swept test's candidates (see sweep_partners()). Allocates only
    /// when the scene grew. With `sorted` false the pairs come in no particular order (event
    /// timing sorts only the few it keeps: the sort is a third of the grid's time in a pile).
    void find_pairs(const ProxySet& set, std::vector<BodyPair>& pairs, bool immovable_pairs = false, bool sorted = true);

    /// The same for `bodies` as they stand, without a swept test (for tests and tools).
    void find_pairs(std::span<const RigidBody> bodies, std::vector<BodyPair>& pairs, bool immovable_pairs = false);

    /// Every pair in index order, without a grid: what find_pairs() falls back to for
    /// bodies at non-finite positions, and what the world uses for a handful of bodies.
    static void all_pairs(std::span<const RigidBody> bodies, std::vector<BodyPair>& pairs, bool immovable_pairs = false);

    static constexpr std::uint32_t partner_may_touch = std::uint32_t{1} << 31;  ///< see sweep_partners()
    static constexpr std::uint32_t partner_index = partner_may_touch - 1;      ///< see sweep_partners()

    /// After a find_pairs() of `set` (the same set): appends to `out` the index of every body
    /// of the set whose bounding sphere (as gathered) comes within `radius` of `centre`, and
    /// of every plane within `radius` of it; conservative by a relative 1e-9. Visits only the
    /// cells near `centre` when there is a grid, every body otherwise.
    ///
    /// `box` (half its sides along each axis, m) narrows the search where the caller keeps
    /// only bodies whose centres lie within a box about `centre`: bodies whose centres lie
    /// outside it by more than rounding are left out, and the grid visits only the cells both
    /// the box and the sphere's reach cover (no body inside both is left out). An infinite or
    /// NaN side narrows nothing along its axis.
    void bodies_near(const ProxySet& set, const Vector3& centre, double radius, std::vector<std::uint32_t>& out,
                     const Vector3& box = unbounded) const;

    /// bodies_near()'s box when the caller asks for none: every side infinite.
    static constexpr Vector3 unbounded{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                                       std::numeric_limits<double>::infinity()};

    /// After a find_pairs() of `set`: body `index` of the set (in set order, not a plane) now
    /// reaches `radius` from its centre, more than when it was gathered; later bodies_near()
    /// queries find it by that radius. Event timing widens a body that an impact sent further
    /// than its reach: a body searching later must find it by where it may now get, not by
    /// where it could get at the start of the step, or two bodies that impacts set moving
    /// towards each other are candidates of neither.
    void widen(ProxySet& set, std::uint32_t index, double radius);

    /// True when the last find_pairs() used a grid (false after it fell back to every pair).
    [[nodiscard]] bool has_grid() const { return has_grid_; }

    /// The world axis (0 x, 1 y, 2 z) along which the last grid laid its rows, the cells that
    /// follow each other in memory (x but for a compact set's: see lay_axes()).
    [[nodiscard]] int row_axis() const { return axis_[0]; }

    /// After a find_pairs() with a swept set and a grid: the bodies whose path may come within
    /// touching distance of fast sphere `body`'s during the step (a superset; each at most once,
    /// in no particular order), as entries: the index (entry & partner_index), and the flag
    /// partner_may_touch unless spheres_may_touch() said no for the two paths as gathered (it
    /// must be asked again if the partner has been moved since). Planes always carry the flag.
    /// Spheres, planes and boxes (boxes always carry the flag). Empty for a body that is not fast.
    [[nodiscard]] std::span<const std::uint32_t> sweep_partners(std::uint32_t body) const {
        if (body + 1 >= sweep_start_.size()) return {};
        return std::span<const std::uint32_t>(sweep_partners_).subspan(sweep_start_[body],
                                                                      sweep_start_[body + 1] - sweep_start_[body]);
    }

private:
    /// Builds the grid over the bounded proxies; false when a position is not finite.
    bool build_grid(const ProxySet& set);
    /// Walks the grid, appending candidate pairs.
    void collect_pairs(const ProxySet& set, bool immovable_pairs);
    /// Appends the pairs of the bounded proxies with the planes.
    void collect_plane_pairs(const ProxySet& set, bool immovable_pairs);
    /// Lays the grid's axes: the world's (x along the rows, then y, then z) for a set that is
    /// not compact, else in the order the set's bodies come (see the definition); `low` and
    /// `cells` along the world's axes.
    void lay_axes(const ProxySet& set, const double (&low)[3], const std::uint64_t (&cells)[3]);
    /// The grid cell along grid axis `axis` of a bounded proxy's coordinate `x` along it (as the
    /// grid placed it). Only a compact set's grid lays its axes other than the world's.
    [[nodiscard]] std::uint64_t axis_cell_of(double x, int axis) const {
        return std::min(static_cast<std::uint64_t>((x - low_[axis]) * inverse_cell_), cells_[axis] - 1);
    }
    /// Sorts contact_keys_ (when `sorted`) into `pairs`, and turns sweep_pairs_ into per-body lists.
    void finish(const ProxySet& set, std::vector<BodyPair>& pairs, bool sorted);

    std::vector<GridProxy> by_cell_;          ///< bounded proxies grouped by cell (a swept set)
    std::vector<CellProxy> small_by_cell_;    ///< the same for a set without the swept test
    bool small_cells_ = false;                ///< the grid is in small_by_cell_ rather than by_cell_
    std::vector<std::uint32_t> cell_of_;      ///< cell of each proxy in set order (for the counting sort)
    std::vector<std::uint32_t> slot_of_;      ///< slot of each proxy in set order in by_cell_ (or small_by_cell_), for widen()
    std::vector<std::uint32_t> cell_start_;   ///< first entry of each cell in by_cell_ (or small_by_cell_)
    std::vector<std::uint32_t> wide_;         ///< slots in by_cell_ of the wide proxies (see build_grid())
    std::vector<std::uint32_t> large_;        ///< slots in by_cell_ of the large proxies
    std::vector<std::uint64_t> contact_keys_; ///< first << 32 | second, before sorting
    std::vector<BodyPair> sweep_pairs_;       ///< (fast sphere, partner entry) for the swept test, any order
    std::vector<std::uint32_t> sweep_start_;  ///< per body, into sweep_partners_
    std::vector<std::uint32_t> sweep_partners_;
    ProxySet scratch_set_;                    ///< for the find_pairs() that gathers itself
    bool has_grid_ = false;
    int axis_[3] = {0, 1, 2};          ///< the world axis of each of the grid's axes, the rows' first
    double low_[3] = {0.0, 0.0, 0.0};  ///< the grid's lowest corner along its axes, m
    double inverse_cell_ = 0.0;        ///< 1 / cell width, 1/m
    std::uint64_t cells_[3] = {1, 1, 1};  ///< cells along the grid's axes
    double slack_ = 0.0;               ///< absolute room for rounding in the swept reach, m
    double largest_radius_ = 0.0;      ///< largest bounding radius in the grid, m
    double margin_ = 0.0;              ///< the set's margin (ProxySet::margin), m
    double largest_reach_ = 0.0;       ///< largest radius + travel in the grid, m
    double small_reach_ = 0.0;         ///< radius + travel above which a proxy is large, m
    double wide_travel_ = 0.0;         ///< travel above which a proxy is wide, m
    std::uint64_t near_cells_ = 1;     ///< how many cells each way a cell is walked against
    /// A proxy that travelled further than wide_travel_ (or a NaN): see build_grid().
    [[nodiscard]] bool is_wide(const GridProxy& p) const { return !(p.travel <= wide_travel_); }
};

}  // namespace workbook
