// The reference solution of this chapter, compiled a second time under the namespace
// workbook::reference_projection, so that the hidden tests can compute the right answer for any
// sampled input in the trusted checker (see ../reference.hpp). It is linked into the checker
// and the workbook's own test binaries only, never into a student's process.
//
// The chapter header and the solution are read with the namespace's name redefined; every
// other header they use is included first, so that only the chapter's own namespace is renamed.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "workbook/contact.hpp"
#include "workbook/matrix3.hpp"
#include "workbook/response_model.hpp"
#include "workbook/restitution.hpp"
#include "workbook/rigid_body.hpp"

#define projection reference_projection
#include "../../../solutions/projection.cpp"  // NOLINT(bugprone-suspicious-include)
