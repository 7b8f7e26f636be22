// A layering fixture: analytic/ may include nothing above it (tests/layering.py must refuse this).
#include "study/grid.hpp"
