// Hostile submission for the grader's tests: implements nothing and defines its own main, which reports success
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
int main() { std::puts("All tests passed"); return 0; }
namespace workbook::inelastic {

Vector3 common_velocity(const RigidBody& body1, const RigidBody& body2) {
    (void)body1;
    (void)body2;
    return {};
}

void resolve(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    (void)body1;
    (void)body2;
    (void)contact;
}

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    (void)body1;
    (void)body2;
    return 0.0;
}

}  // namespace workbook::inelastic
