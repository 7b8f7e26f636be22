// A layering fixture: the kit, which adapters link in, may not reach the host (tests/layering.py must refuse this).
#include "multibody/host/registry.hpp"
