#pragma once
// How long the chapter tests step a scene in the sanitizer build (build/sanitize), the same
// rule as plots/motion.py's is_heavy() and for_sanitizers(): the sanitizers slow a step some
// 20 times and catch memory and undefined-behaviour errors in a short stretch of a scene as
// well as in the whole, so there a heavy scene (more than 100 body-seconds: chapter 5's pile,
// column, pyramid and minute-long stacks) runs its first half second only. The dev build's
// tests step every scene as far as they say.
#include <algorithm>
#include <cstddef>

#include "workbook/scene.hpp"
#include "workbook/time_series.hpp"

namespace workbook::testing {

#ifdef WORKBOOK_UNDER_SANITIZERS
inline constexpr bool under_sanitizers = true;
#else
inline constexpr bool under_sanitizers = false;
#endif

inline constexpr double heavy_body_seconds = 100.0;
inline constexpr double sanitized_seconds = 0.5;

/// True for a scene of more than heavy_body_seconds body-seconds (bodies x duration).
inline bool is_heavy(const Scene& scene) {
    return static_cast<double>(scene.bodies.size()) * scene.duration > heavy_body_seconds;
}

/// At most `steps`, and in the sanitizer build at most a heavy scene's first sanitized_seconds.
inline std::size_t sanitized_steps(const Scene& scene, std::size_t steps) {
    if (!under_sanitizers || !is_heavy(scene)) return steps;
    return std::min(steps, step_count(std::min(scene.duration, sanitized_seconds), scene.settings.time_step));
}

}  // namespace workbook::testing
