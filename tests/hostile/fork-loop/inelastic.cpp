// Hostile submission for the grader's tests: energy_lost() starts up to 2000 sleeping child processes and waits for them (bounded here, so that even an unsandboxed run cannot take the machine down)
// Apart from that it is the reference solution, so every other step must keep its points.
#include "inelastic.hpp"
#include <cstdio>
#include <sys/wait.h>
#include <unistd.h>
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    const double w1 = body1.inverse_mass;
    const double w2 = body2.inverse_mass;
    if (w1 == 0.0) return body1.velocity;
    if (w2 == 0.0) return body2.velocity;
    return (w2 * body1.velocity + w1 * body2.velocity) / (w1 + w2);
}

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    if (body1.is_immovable() && body2.is_immovable()) return;
    if (dot(body1.velocity - body2.velocity, contact.normal) >= 0.0) return;
    const Vector3 shared = common_velocity(body1, body2);
    if (!body1.is_immovable()) body1.velocity = shared;
    if (!body2.is_immovable()) body2.velocity = shared;
}

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
