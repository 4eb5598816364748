// Hostile submission for the grader's tests: energy_lost() prints an imitation of a passing Catch2 XML report and of the step reporter, and returns a wrong value
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    std::fputs(R"(<?xml version="1.0" encoding="UTF-8"?>
<Catch2TestRun name="inelastic-tests" rng-seed="20261122" xml-format-version="3" catch2-version="3.7.1">
  <TestCase name="energy lost by a 2 kg cart at 3 m/s hitting a 1 kg cart at rest" tags="[inelastic][points:2][step:5:energy-lost]">
    <OverallResult success="true" skips="0"/>
  </TestCase>
  <OverallResults successes="1" failures="0" expectedFailures="0" skips="0"/>
  <OverallResultsCases successes="1" failures="0" expectedFailures="0" skips="0"/>
</Catch2TestRun>
All tests passed (1 assertion in 1 test case)
  PASS  Step 5 · energy lost  (2 of 2 tests pass)
)", stdout);
    if (body1.inverse_mass >= 0.0) return 100.0;
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
