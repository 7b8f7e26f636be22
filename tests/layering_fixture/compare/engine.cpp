// A layering fixture: an engine header outside its adapter (tests/layering.py must refuse this).
#include <ode/ode.h>
