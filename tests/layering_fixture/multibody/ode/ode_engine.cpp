// A layering fixture: an adapter including compare/ (tests/layering.py must refuse this).
#include "compare/experiments.hpp"
