// A layering fixture: an engine folder's own test including tests/ and compare/ (tests/layering.py accepts it).
#include "tests/engine_available.hpp"
#include "compare/experiments.hpp"
