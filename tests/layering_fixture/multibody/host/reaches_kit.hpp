// A layering fixture: the host may take from the kit only its settings and step checks (tests/layering.py must
// refuse this).
#include "multibody/kit/run_monitor.hpp"
