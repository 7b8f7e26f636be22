// A layering fixture: a relative include that climbs out of analytic/ into study/ (tests/layering.py must refuse it
// twice: for the ../ and for the folder it reaches).
#include "../study/grid.hpp"
