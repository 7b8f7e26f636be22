"""The Python module's promise for input, as a property (docs/guide/python.md, "Errors"): on random arguments drawn
from valid values and from the extremes that broke it before, each call of vssw.simulate, vssw.compare and
vssw.study either returns a result or raises vssw.InputError (a ValueError), TypeError, OverflowError (an integer
no float holds) or vssw.SimulationError — never a crash of the interpreter, another exception, or a control
character in a message. Arguments drawn valid must return a result; arguments certainly bad must raise InputError,
TypeError or OverflowError.

Each call runs in an interpreter of its own, so that a signal kills only its case. Seeded: VSSW_PROPERTY_SEED
explores another sample, VSSW_PROPERTY_CASES sets the calls per function.
"""
import concurrent.futures
import json
import os
import random
import re
import subprocess
import sys

import pytest

from conftest import REPO

# The seed of the deterministic sample CI runs (any fixed number; the date the test was written).
DEFAULT_SEED = 20261128
SEED = int(os.environ.get("VSSW_PROPERTY_SEED", DEFAULT_SEED))
# Calls per function: each is an interpreter start (~0.1 s) and a cheap run (analytic or ODE, ~0.1-0.5 s).
CASES = int(os.environ.get("VSSW_PROPERTY_CASES", "24"))
# Per call: ten times the slowest valid call drawn here (ODE under a pulse on a busy machine, ~3 s).
CALL_TIMEOUT_S = 30
JOBS = 2  # the CI machine's cores
# What a message must never carry raw: C0 controls but the line break and tab, DEL, C1.
CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f\x80-\x9f]")

FIG6 = {"height": 4.0, "thickness": 0.4, "hinge": 0.7}
PULSE = {"pulse": "sine", "amplitude": 0.5, "pulse_period": 0.5}
# Python values no numeric argument takes (as source text: the child evaluates it).
BAD_NUMBERS = ["float('nan')", "float('inf')", "-float('inf')", "'4'", "[]", "None if False else {}", "1e400",
               "complex(1, 1)", "b'4'"]
# Values that may be valid or not (then only the promise holds).
EDGE_NUMBERS = ["0", "-0.0", "-1", "1e-310", "1e308", "True", "10**400", "decimal.Decimal('4')",
                "fractions.Fraction(4)", "numpy.float64(4)"]
# Engine arguments no call takes: a repeated or empty item, a trailing comma, an unknown or control-laden name.
BAD_ENGINES = ["['ode', 'ode']", "[]", "'ode,'", "''", "'ODE\\x1b[2J'", "'nope'", "['analytic', '']"]


def call_source(function, kwargs, positional=""):
    """The child's program: one call, its outcome as one JSON line on stdout."""
    args = ", ".join([positional] * bool(positional) + ["%s=%s" % kv for kv in kwargs.items()])
    return (
        "import decimal, fractions, json, math, sys, tempfile, numpy\n"
        "import vssw\n"
        "try:\n"
        "    vssw.%s(%s)\n"
        "    outcome, message = 'result', ''\n"
        "except vssw.InputError as e:\n"
        "    outcome, message = 'InputError', str(e)\n"
        "except vssw.SimulationError as e:\n"
        "    outcome, message = 'SimulationError', str(e)\n"
        "except (TypeError, OverflowError) as e:\n"
        "    outcome, message = type(e).__name__, str(e)\n"
        "print(json.dumps({'outcome': outcome, 'message': message}))\n" % (function, args))


def draw_simulate(rng):
    kwargs = {k: repr(v) for k, v in FIG6.items()}
    engine = rng.choice(["'analytic'", "'analytic'", "'ode'"])
    kwargs["theta0"] = repr(round(rng.uniform(0.2, 0.8), 3))
    if rng.random() < 0.4:
        kwargs.pop("theta0")
        kwargs.update({k: repr(v) for k, v in PULSE.items()})
    if engine != "'ode'":
        kwargs["t_end"] = "3.0"
    return "simulate", engine, kwargs


def draw_compare(rng):
    kwargs = {k: repr(v) for k, v in FIG6.items()}
    kwargs.update({k: repr(v) for k, v in PULSE.items()})
    return "compare", rng.choice(["'ode'", "['ode']", "'bullet'"]), kwargs


def draw_study(rng):
    doc = {"name": "p", "metrics": ["threshold_closed_form_g"], "wall": {"height": [3.0, 4.0], "thickness": 0.4,
                                                                          "hinge": 0.7},
           "excitation": {"kind": "closed-form"}}
    return "study", repr(doc), {"out": "tempfile.mkdtemp() + '/o'"}


DRAWS = {"simulate": draw_simulate, "compare": draw_compare, "study": draw_study}


def spoil(rng, function, positional, kwargs):
    """0-2 edits: a numeric argument replaced by an extreme, the engine list spoiled, a study dict key spoiled, a
    progress that is no callable. Returns (positional, kwargs, why certainly bad or '', whether still valid)."""
    bad, edits = "", rng.choice([0, 1, 1, 2])
    for _ in range(edits):
        op = rng.random()
        numeric = [k for k in kwargs if k not in ("pulse", "out")]
        if op < 0.45 and numeric:
            k = rng.choice(numeric)
            v = rng.choice(BAD_NUMBERS + EDGE_NUMBERS)
            kwargs[k] = v
            bad = bad or ("%s=%s" % (k, v) if v in BAD_NUMBERS else "")
        elif op < 0.7 and function in ("simulate", "compare"):
            positional = rng.choice(BAD_ENGINES)
            bad = bad or ("engine %s" % positional if function == "compare" or positional != "[]" else "")
        elif op < 0.85 and function == "study":
            key = rng.choice(["'nope'", "'bad\\x1b[2J'", "'name'"])
            value = rng.choice(["float('nan')", "'a\\x00b'", "'\\ud800'", "1"])
            positional = "dict(%s, **{%s: %s})" % (positional, key, value)
            bad = bad or "study key %s = %s" % (key, value)
        elif function != "simulate":
            kwargs["progress"] = rng.choice(["123", "'yes'"])
            bad = bad or "progress %s" % kwargs["progress"]
    return positional, kwargs, bad, edits == 0


def run_call(source):
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    done = subprocess.run([sys.executable, "-c", source], capture_output=True, text=True, timeout=CALL_TIMEOUT_S,
                          env=env, cwd=REPO, errors="surrogateescape")
    return done.returncode, done.stdout, done.stderr


@pytest.mark.parametrize("function", list(DRAWS))
def test_every_call_keeps_the_promise(function):
    rng = random.Random("%d:%s" % (SEED, function))
    cases = []
    for _ in range(CASES):
        name, positional, kwargs = DRAWS[function](rng)
        positional, kwargs, bad, valid = spoil(rng, name, positional, kwargs)
        cases.append((call_source(name, kwargs, positional), bad, valid))
    with concurrent.futures.ThreadPoolExecutor(max_workers=JOBS) as pool:
        results = list(pool.map(lambda c: run_call(c[0]), cases))
    broken = []
    for (source, bad, valid), (code, out, err) in zip(cases, results):
        call = source.splitlines()[3].strip()
        if code != 0:
            broken.append("%s: interpreter ended with %d: %s" % (call, code, err.strip().splitlines()[-1:]))
            continue
        outcome = json.loads(out.strip().splitlines()[-1])
        if CONTROL.search(outcome["message"]):
            broken.append("%s: a control character in the message %r" % (call, outcome["message"][:120]))
        if valid and outcome["outcome"] != "result":
            broken.append("%s: valid arguments raised %s: %s" % (call, outcome["outcome"], outcome["message"][:160]))
        if bad and outcome["outcome"] not in ("InputError", "TypeError", "OverflowError"):
            broken.append("%s: certainly bad (%s) but %s" % (call, bad, outcome["outcome"]))
    assert not broken, "seed %d (VSSW_PROPERTY_SEED):\n" % SEED + "\n".join(broken)
