// Hostile submission for the grader's tests: energy_lost() starts up to 2000 sleeping child processes and waits for them (bounded here, so that even an unsandboxed run cannot take the machine down)
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#include <sys/wait.h>
#include <unistd.h>
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    {
        int children = 0;
        for (; children < 2000; ++children) {
            const pid_t pid = fork();
            if (pid < 0) break;
            if (pid == 0) {
                sleep(30);
                _exit(0);
            }
        }
        std::fprintf(stderr, "fork loop: %d children started%s\n", children, children < 2000 ? ", then fork failed" : "");
        std::fflush(stderr);
        while (wait(nullptr) > 0) {
        }
    }
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}

}  // namespace workbook::inelastic
