// The seed's method (src/bounce/seed_method.cpp) built a second time with -O3 -march=native
// (bench/CMakeLists.txt), as seed_contact_native: the baseline as a careful engineer would
// compile it for this machine (no run-time CPU dispatch: -march=native already targets it).
#define TRIBOLAB_SEED_CONTACT_FN seed_contact_native
#define TRIBOLAB_SEED_NO_DISPATCH
#include "bounce/seed_method.cpp"
