#pragma once
/// \file
/// The stress corpus: scenes that break naive engines, with invariants checked after every step.
///
/// Invariants, each as a ratio of what was measured to what is allowed (<= 1 passes):
///  - finite:   every number of every body stays finite (the world's guard; a throw fails the scene);
///  - energy:   for e <= 1, total energy never rises above its start by more than rounding,
///              16 eps (n + 1) E_scale after n steps, E_scale = sum of 1/2 m |v|^2 + m |g| |x| at
///              the start (each step rounds each energy term at most a few times);
///  - momentum: where no external force acts (no gravity, no immovable body), |P(n) - P(0)| <=
///              16 eps (n + 1) P_scale, P_scale = sum of m |v| at the start;
///  - box:      in a closed box, no centre ever lies outside a wall by more than 64 eps times
///              the box's distance from the origin plus its size.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "workbook/response_model.hpp"
#include "workbook/world.hpp"

namespace workbook::accuracy {

/// An axis-aligned closed box of six immovable planes, m.
struct Box {
    Vector3 low;   ///< the corner with the smallest coordinates
    Vector3 high;  ///< the opposite corner
};

/// One scene of the corpus.
struct StressScene {
    std::string name;         ///< short id, the table's first column
    std::string what;         ///< what it stresses, one line
    std::function<World(const ResponseModel&)> build;
    std::uint64_t steps = 0;  ///< how many steps to run
    bool check_energy = true;    ///< every body has e <= 1
    /// J the total energy may gain beyond rounding. 0 but for the scenes of resting contact: a
    /// contact solver answers to its tolerance and its cap of passes, not to rounding, and
    /// the velocity it leaves a resting body (below a micrometre a second once settled) lifts
    /// it a little; those scenes allow every body a rise of 1 micrometre, a two-thousandth of
    /// the slop, for it.
    double energy_allowance = 0.0;
    bool check_momentum = false;  ///< no gravity and no immovable body
    std::optional<Box> box;       ///< the closed box, if the scene has one
    /// A check of the scene's own, after every step: measured / allowed (<= 1 passes), and its name.
    std::function<double(const World&)> own_check;
    std::string own_check_name;
    /// A scene of resting contact (stacks and piles) is about the contact solver, which only the
    /// responders of chapters 5 and 6 have: it runs with the one named here, whatever model the
    /// corpus runs with. Empty: the corpus's model.
    std::string responder;
};

/// The outcome of one scene.
struct StressResult {
    std::string scene;
    std::uint64_t steps = 0;       ///< steps actually run (fewer when the guard stopped it)
    std::size_t bodies = 0;
    double worst = 0.0;            ///< the largest measured / allowed ratio over all invariants and steps
    std::string worst_invariant;   ///< which invariant that ratio belongs to
    double energy_ratio = 0.0;     ///< worst ratio of each invariant (0 when not checked)
    double momentum_ratio = 0.0;
    double box_ratio = 0.0;
    double box_escape = 0.0;       ///< m: the furthest any centre lay outside a wall
    std::string error;             ///< the guard's message when a number went non-finite
    double seconds = 0.0;          ///< wall time of the run, invariants included
    [[nodiscard]] bool passed() const { return error.empty() && worst <= 1.0; }
};

/// A scene file the loader must refuse, naming the field.
struct RefusedScene {
    std::string name;   ///< short id, the table's first column
    std::string what;   ///< what is wrong with it, one line
    std::function<std::string()> text;  ///< the file's text (built on demand: one is 20 MB)
    std::string field;  ///< the field the refusal must name
};

/// The scene files the loader must refuse: absurd input of every kind the limits cover.
std::vector<RefusedScene> refused_scenes();

/// The refusal's field and message, or "accepted" when the loader took the scene.
struct RefusalResult {
    std::string scene;
    std::string field;    ///< the field the refusal named (empty when accepted)
    std::string message;  ///< the whole message, or "accepted"
    double seconds = 0.0;
    bool passed = false;  ///< refused, naming the expected field
};

/// Loads one refused scene and checks its refusal.
RefusalResult check_refusal(const RefusedScene& scene);

/// The corpus: `full` is the on-demand version (10,000 bodies, 10^6 steps); otherwise the small
/// version the test suite runs in a few seconds.
std::vector<StressScene> stress_corpus(bool full);

/// Runs one scene with `model`, checking every invariant after every step. `progress` is
/// called now and then with the steps done.
StressResult run_stress(const StressScene& scene, const ResponseModel& model,
                        const std::function<void(std::uint64_t)>& progress = {});

}  // namespace workbook::accuracy
