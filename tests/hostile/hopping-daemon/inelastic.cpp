// Hostile submission for the grader's tests: energy_lost() leaves a process in a session of its own that keeps moving to a new pid (it forks and the parent exits, over and over) for a minute, to outrun whatever kills the test case's processes
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <ctime>
#include <unistd.h>
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    if (fork() == 0) {
        setsid();
        const std::time_t end = std::time(nullptr) + 60;
        while (std::time(nullptr) < end) {
            const pid_t child = fork();
            if (child > 0) _exit(0);  // the parent leaves, the child carries on under a new pid
            if (child < 0) usleep(1000);
        }
        _exit(0);
    }
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}
}  // namespace workbook::inelastic
