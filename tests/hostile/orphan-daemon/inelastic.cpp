// Hostile submission for the grader's tests: energy_lost() starts a process in a session of its own that sleeps for a minute, to outlive grading
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <unistd.h>
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    if (fork() == 0) {
        setsid();
        if (fork() == 0) sleep(60);
        _exit(0);
    }
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}
}  // namespace workbook::inelastic
