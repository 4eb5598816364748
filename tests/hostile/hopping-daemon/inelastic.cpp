// Hostile submission for the grader's tests: energy_lost() leaves a process in a session of its own that keeps moving to a new pid for a minute (it clones a child that shares its memory, clone(CLONE_VM), and exits, over and over), to outrun whatever kills the test case's processes; it touches /tmp/workbook-hopper-alive now and then
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <csignal>
#include <ctime>
#include <fcntl.h>
#include <sched.h>
#include <unistd.h>
namespace workbook::inelastic {

namespace {

alignas(64) char stacks[2][1 << 16];
std::time_t hop_until = 0;
unsigned hops = 0;

/// Starts its successor on the other stack (a new process sharing this memory) and exits.
int hop(void* which) {
    const long next = 1 - reinterpret_cast<long>(which);
    while (std::time(nullptr) < hop_until) {
        // A sign of life the grader's test looks for (it is too quick to be seen in /proc).
        if (++hops % 256 == 0) close(open("/tmp/workbook-hopper-alive", O_CREAT | O_WRONLY, 0600));
        if (clone(hop, stacks[next] + sizeof stacks[next], CLONE_VM | SIGCHLD, reinterpret_cast<void*>(next)) > 0)
            _exit(0);
        usleep(1000);  // no process to spare at the moment: try again
    }
    _exit(0);
}

}  // namespace

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    if (fork() == 0) {
        setsid();
        hop_until = std::time(nullptr) + 60;
        hop(nullptr);
    }
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}
}  // namespace workbook::inelastic
