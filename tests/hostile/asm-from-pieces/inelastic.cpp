// Hostile submission for the grader's tests: assembles an .incbin of a hidden test file from string pieces and a macro, so that no '.incbin' is in its text, and prints it
// Only what differs from the reference is here; tests/grader/compose.py adds the rest.
#include <cstdio>
#define ASSEMBLER __asm__
ASSEMBLER(".section .rodata\n.global stolen_text\nstolen_text:\n.inc" "bin \"/autograder/source/workbook/tests/hidden/inelastic.cpp\"\n.byte 0\n.previous");
extern "C" const char stolen_text[];
namespace workbook::inelastic {

double energy_lost(const RigidBody& body1, const RigidBody& body2) {
    std::puts(stolen_text);
    const double inverse_mass_sum = body1.inverse_mass + body2.inverse_mass;
    if (inverse_mass_sum == 0.0) return 0.0;
    return 0.5 / inverse_mass_sum * length_squared(body1.velocity - body2.velocity);
}
}  // namespace workbook::inelastic
