#pragma once
// Williams' balanced Latin square (Williams 1949, Aust. J. Sci. Res. A 2): first-order carry-over
// balanced. Row 0 is 0, 1, n-1, 2, n-2, ...; row r adds r (mod n). For even n, n rows in which
// every ordered pair of distinct levels is adjacent exactly once. For odd n no single square does
// this, so the design is doubled: the n rows and their n reversals (2n rows, each ordered pair
// adjacent exactly twice).
#include "study/design/latin_square.hpp"

namespace tlab::study {

OrderTable williamsDesign(int n);

}  // namespace tlab::study
