"""Property test of the vssw program's promise for input (docs/guide/program.md "The `vssw` program", "Bad input"; cli/cli.hpp's
exit codes), on the real built program run as a subprocess so that a signal or a hang is seen.

Every command is run on random option values from a seeded generator: valid values, values at the edges of their
ranges, and the extremes that broke the promise before (empty strings, 0, -0, 1e-310, 1e308, nan, inf, huge
integers, Unicode digits, very long strings, lists with empty or repeated items, repeated options, single-dash long
words, paths to missing files, folders and devices, file names with backticks, $(...), quotes, newlines and non-ASCII
letters), and `vssw study` on random small study files (TOML and JSON, valid and broken). Each run must:

  - end with exit 0, 2 or 3 (1 too for `check`: a bound out), never by a signal, within RUN_TIMEOUT_S;
  - on exit 2, write exactly one line on stderr, starting "vssw: error:";
  - on exit 3, name the failure on a stderr line starting "vssw: simulation failed:";
  - on exit 1 (check), name the bound on a stderr line starting "vssw: check failed:";
  - on exit 0 with --json, print JSON with no NaN or infinity (nor as a string), and write none into a .json file;
  - create or change no file outside its own --out and --csv paths (its scratch folder, which holds its inputs and
    is its working directory and $HOME, is compared before and after), and never change an input file;
  - for `study`, on exit 2 leave no --out folder it did not find (docs/guide/studies.md: refused before any folder is made).

The runs are deterministic for a seed: VSSW_PROPERTY_SEED (default DEFAULT_SEED) picks another sample to explore
more, VSSW_PROPERTY_CASES the number of cases per command. A failure lists every broken run by class, with its
command line, exit code and first stderr line; the failing runs' folders are kept under VSSW_PROPERTY_WORK (or a
temporary folder) to replay them: `cd <folder> && HOME=$PWD <command line>`.

Environment: VSSW_EXECUTABLE (the program), VSSW_DATA_DIR (the shipped data/ with the records).
Run: VSSW_EXECUTABLE=build/vssw VSSW_DATA_DIR=data python3 -m pytest -q -p no:cacheprovider tests/cli/test_cli_properties.py
"""

import concurrent.futures
import hashlib
import json
import math
import os
import random
import re
import shlex
import shutil
import signal
import subprocess
import tempfile
import time

import pytest

import property_surface as surface

# --- constants -----------------------------------------------------------------------------------------------------

# The seed of the deterministic sample CI runs (any fixed number; the date the test was written).
DEFAULT_SEED = 20261125
SEED = int(os.environ.get("VSSW_PROPERTY_SEED", DEFAULT_SEED))
# Cases per command: enough to draw each kind of extreme a few times, few enough that the whole test stays near 60 s
# on 2 busy cores (a valid run here takes 0.05-0.5 s, an engine's threshold up to ~3 s, a Simbody free vibration ~12 s).
DEFAULT_CASES = 60
CASES = int(os.environ.get("VSSW_PROPERTY_CASES", DEFAULT_CASES))
# Per run: well past the slowest valid run drawn here, so that only a hang reaches it; a run past it is killed (its
# whole process group: ODE's workers too) and fails. The slowest seen: a study of four Simbody free vibrations of a
# 2.1 m parapet (seed 20261125, run 65), 22.8 s on a quiet machine (one such run 11.6 s, Simbody's compliant route),
# past 30 s beside the rest of the suite on 2 cores; 90 s is four times the quiet figure.
RUN_TIMEOUT_S = 90
# Runs at once: the CI machine has 2 cores; more would only slow each run towards the timeout.
JOBS = int(os.environ.get("VSSW_PROPERTY_JOBS", "2"))
# Files above this are compared by size and time only (hashing a large output would only cost time; inputs are small).
HASH_LIMIT_BYTES = 4 << 20
# VSSW_PROPERTY_VERBOSE=1 prints every run (command line, exit code, first stderr line): to look at what is drawn.
VERBOSE = os.environ.get("VSSW_PROPERTY_VERBOSE") == "1"
# How much of a generated input file a failure report shows (a study file is a few hundred bytes).
SHOW_FILE_CHARS = 600

# Absolute: every run starts in a folder of its own.
VSSW = os.path.abspath(os.environ.get("VSSW_EXECUTABLE", "build/vssw"))
DATA = os.path.abspath(os.environ.get("VSSW_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data")))

# The wall of the paper's Fig. 6, and a cheap valid value for each wall option.
FIG6 = {"--height": "4", "--thickness": "0.4", "--hinge": "0.7"}

# --- values --------------------------------------------------------------------------------------------------------

# Number-like strings that broke (or nearly broke) the promise: empty, signed zero, underflow, overflow, not finite,
# integer overflow, Unicode digits (Arabic-Indic four, fullwidth four), a decimal comma, hex, junk, whitespace,
# a 5000-digit number and a 5000-character word.
EXTREME_NUMBERS = [
    "", " ", "0", "-0", "-0.0", "-1", "1e-310", "4.9e-324", "1e308", "-1e308", "1.7976931348623157e308", "1e99999",
    "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "99999999999999999999", "18446744073709551617",
    "-9223372036854775809", "2147483648", "\u0664", "\uff14", "1,5", "0x10", "0x1p-2", "4.0.0", "1e", "4 ", " 4",
    "+4", "4\n", "9" * 5000, "x" * 5000, "$(touch PWNED)", "`touch PWNED`", "'", "\"", "-h", "--json",
]
# Words for options that take a name: empty, case, spaces, lists with empty and repeated items, long, non-ASCII.
EXTREME_WORDS = [
    "", " ", ",", ",,", "PAPER", "exact ", " exact", "exact,exact", "ex\u00e4ct", "x" * 5000, "-1", "nan",
    "$(touch PWNED)", "`touch PWNED`", "a\nb", "\t",
]


def fmt_number(x):
    """A float as a user would type it: %g, or repr when %g would lose a boundary value."""
    s = "%.6g" % x
    return s if float(s) == x else repr(x)


def uniform(rng, lo, hi, log=False):
    if log:
        return math.exp(rng.uniform(math.log(lo), math.log(hi)))
    return rng.uniform(lo, hi)


def boundary_values(lo, hi):
    """The ends of a range and a hair beyond each (relative 1e-9: outside, not rounded onto the end)."""
    out = []
    for x in (lo, hi):
        out += [x, x * (1 - 1e-9) if x > 0 else x - 1e-9, x * (1 + 1e-9) if x > 0 else x + 1e-9]
    return [fmt_number(x) for x in out]


class Num:
    """A numeric option: valid values drawn from [lo, hi] (log-uniform when log), edges from [edge_lo, edge_hi]."""

    def __init__(self, lo, hi, log=False, edges=None, integer=False):
        self.lo, self.hi, self.log, self.integer = lo, hi, log, integer
        self.edges = edges

    def valid(self, rng):
        x = uniform(rng, self.lo, self.hi, self.log)
        return str(int(round(x))) if self.integer else "%.4g" % x  # as typed: a few digits

    def edge(self, rng):
        lo, hi = self.edges or (self.lo, self.hi)
        return rng.choice(boundary_values(lo, hi))

    def extreme(self, rng):
        return rng.choice(EXTREME_NUMBERS)


class Word:
    """An option that takes one of a few words (or a comma-separated list of them when listy)."""

    def __init__(self, words, listy=False):
        self.words, self.listy = list(words), listy

    def valid(self, rng):
        if self.listy and rng.random() < 0.3:
            return ",".join(rng.sample(self.words, min(len(self.words), 2)))
        return rng.choice(self.words)

    def edge(self, rng):
        w = rng.choice(self.words)
        if self.listy:
            return rng.choice([w + ",", "," + w, w + ",," + w, w + "," + w, w.upper(), "all"])
        return rng.choice([w.upper(), w + " ", w[:-1]])

    def extreme(self, rng):
        return rng.choice(EXTREME_WORDS)


class Path:
    """An input file option: the run's own copies of the records, or an odd path."""

    def __init__(self, valid_paths, odd_paths):
        self.valid_paths, self.odd_paths = valid_paths, odd_paths

    def valid(self, rng):
        return rng.choice(self.valid_paths)

    def edge(self, rng):
        return rng.choice(self.odd_paths)

    def extreme(self, rng):
        return rng.choice(self.odd_paths + ["", "x" * 5000])


class Out:
    """An output option (--out, --csv): a fresh path in the run's folder, or an odd one (a record, a folder, ...)."""

    def __init__(self, valid_paths, odd_paths):
        self.valid_paths, self.odd_paths = valid_paths, odd_paths

    def valid(self, rng):
        return rng.choice(self.valid_paths)

    edge = extreme = lambda self, rng: rng.choice(self.odd_paths)


# Record files each run's folder holds (copies of the shipped data/, see make_inputs): names a shell or gnuplot would
# take for commands (backticks, $(...), a newline followed by gnuplot's '!'), quotes, non-ASCII letters, a long name.
# A command run from a name writes PWNED* into $HOME, the run's folder: a file outside --out, caught as such.
ODD_RECORD_NAMES = [
    "r`cd;touch PWNED1`.AT2", "r$(cd;touch PWNED2).AT2", "r'q\"uote.AT2", "r\n!cd;touch PWNED3\n.AT2",
    "r\u00e9cord-\u00fc.AT2", "r" * 200 + ".AT2", "r -h.AT2", "-r.AT2",
]
RECORDS = ["rec.AT2", "elc.txt", "results.csv"] + ODD_RECORD_NAMES
ODD_INPUT_PATHS = ["missing.AT2", "adir", "adir/", "/dev/null", "/dev/zero", "empty.txt", "junk.bin", "/proc/self/environ",
                   "rec.AT2/x", "./rec.AT2", "x" * 300 + ".AT2"]
# Outputs a case names with --out and --csv (any other value of theirs is odd: ODD_OUTS).
OUT_DIRS = ["out", "out2/sub", "o \u00e9`x`"]
CSV_FILES = ["traj.csv", "t r'a\u00e9j.csv"]
ODD_OUTS = ["", "rec.AT2", "adir", "empty.txt", "/dev/null", "out/", ".", "x" * 5000]

WALL = {
    "--height": Num(1.0, 8.0, edges=(0.001, 1000.0)),
    "--thickness": Num(0.1, 0.5, edges=(0.001, 1000.0)),
    "--hinge": Num(0.3, 0.95, edges=(0.0, 1.0)),
    "--xi": Num(0.0, 0.5, edges=(0.0, 1000.0)),
    "--density": Num(1200.0, 2400.0, edges=(1.0, 100000.0)),
    "--g": Num(9.0, 10.0, edges=(0.01, 1000.0)),
    "--model": Word(["vssw", "parapet"]),
    "--assumptions": Word(["paper", "mechanism"]),
    "--kinematics": Word(["paper", "exact"]),
    "--impact": Word(["eq19", "whole-mechanism", "0.5", "0", "1"]),
    "--roller": Word(["bilateral", "unilateral"]),
}
RECORD = Path(["rec.AT2", "elc.txt"], ODD_RECORD_NAMES + ODD_INPUT_PATHS)
MOTION_RECORD = {
    "--record": RECORD,
    "--pga": Num(0.1, 0.5, edges=(0.0, 100.0)),
    "--scale": Num(0.1, 1.5, edges=(0.0, 1000.0)),
    "--units": Word(["g", "m/s2", "cm/s2"]),
}
MOTION_PULSE = {
    "--pulse": Word(["sine", "cosine", "ricker"]),
    "--amplitude": Num(0.2, 1.0, edges=(0.0, 100.0)),
    "--pulse-period": Num(0.2, 1.0, edges=(0.0, 1e6)),
}
# Options a generator may add that belong to another command, or to none (must be refused: exit 2).
STRAY_OPTIONS = ["--heigth", "--engine", "--engines", "--out", "--csv", "--record", "--pulse", "--theta0", "--set",
                 "--threads", "--bounds", "--suite", "--json", "--strict", "--version", "-x", "--", "---height"]


# --- cases ---------------------------------------------------------------------------------------------------------


class Case:
    """One run: argv after the program, what it may write, whether stdout is JSON, and files to create first."""

    def __init__(self, command, args, json_out=False, files=None, out_dirs=(), inputs=(), bad=(), valid=False,
                 setup=None, env=None):
        self.command, self.args, self.json_out = command, list(args), json_out
        self.files = dict(files or {})  # name -> text, written into the run's folder before it runs
        self.out_dirs = out_dirs        # --out values (exit 2 must leave no new folder there)
        self.inputs = list(inputs)      # files the run reads that its arguments do not name (a study's records)
        self.bad = list(bad)            # why the input is certainly bad (then it must exit 2), empty if it may be valid
        self.valid = valid and not bad  # valid as drawn: then it must succeed (exit 0)
        self.setup = setup              # setup(folder): inputs a text cannot hold (symlinks, FIFOs, damaged plugins)
        self.env = dict(env or {})      # more environment (VSSW_PLUGIN_PATH)
        self.index = 0

    def line(self):
        return " ".join(shlex.quote(a) for a in [VSSW] + self.args)


def assemble(opts, positional=()):
    """(option, value) pairs to argv; a value of None is a flag."""
    argv = list(positional)
    for opt, value in opts:
        argv.append(opt)
        if value is not None:
            argv.append(value)
    return argv


# Values no option of the kind can take: not numbers at all, not finite, or no word the option knows. An edit that
# puts one in makes the case "certainly bad": it must be refused with exit 2 (docs/guide/program.md "Bad input"). Edges and the other
# extremes (-0, 1e-310, 1e308, hex, " 4", upper case, ...) may be valid somewhere and are only held to the promise.
BAD_NUMBERS = {"", " ", "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e99999", "\u0664", "\uff14", "1,5", "4.0.0",
               "1e", "x" * 5000, "$(touch PWNED)", "`touch PWNED`", "'", "\""}
BAD_WORDS = {"", ",", ",,", "x" * 5000, "nan", "$(touch PWNED)", "`touch PWNED`", "a\nb", "\t", "ex\u00e4ct",
             "exact,exact"}
BAD_INPUT_PATHS = {"", "missing.AT2", "adir", "adir/", "/dev/null", "/dev/zero", "empty.txt", "junk.bin",
                   "/proc/self/environ", "rec.AT2/x", "x" * 300 + ".AT2", "x" * 5000}
BAD_OUTS = {"", "x" * 5000}


def certainly_bad(kind, value):
    """Whether an option of this kind can never take the value."""
    if isinstance(kind, Num):
        return value in BAD_NUMBERS
    if isinstance(kind, Word):
        # A list with an empty or a repeated item: "each engine named once" (docs/guide/program.md), and likewise for every list.
        items = value.split(",")
        listy_bad = kind.listy and ("" in items or len(set(items)) < len(items))
        return value in BAD_WORDS or listy_bad or (not kind.listy and "," in value and value != "1,5")
    if isinstance(kind, Path):
        return value in BAD_INPUT_PATHS
    if isinstance(kind, Out):
        return value in BAD_OUTS
    return False


_HELP_CACHE = {}


def command_options(command):
    """The options `vssw COMMAND --help` lists, and those it marks as taking several values ("TEXT ...")."""
    if command not in _HELP_CACHE:
        text = subprocess.run([VSSW] + command.split() + ["--help"], capture_output=True, text=True,
                              timeout=RUN_TIMEOUT_S).stdout
        known, multi = set(), set()
        for line in text.splitlines():
            words = line.strip().split()
            if not words or not words[0].startswith("-"):
                continue
            for name in words[0].split(","):
                known.add(name)
                if "..." in words[1:3]:
                    multi.add(name)
        _HELP_CACHE[command] = (known, multi)
    return _HELP_CACHE[command]


def mutate(rng, opts, spec, command):
    """Applies 1-3 edits to a valid option list: a value at its edge or an extreme one, an option dropped, repeated,
    given with one dash or as --opt=value, an option from elsewhere, help. Returns the new list and why it is certainly
    bad input (empty when it may be valid)."""
    opts, value_bad = list(opts), []  # value_bad: (the option entry, why its value is certainly bad)
    known, multi = command_options(command)
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        op = rng.random()
        idx = rng.randrange(len(opts)) if opts else None
        name = opts[idx][0] if opts else None
        if idx is not None and opts[idx][1] is not None and name in spec and op < 0.30:
            value = spec[name].extreme(rng)
            opts[idx] = (name, value)
            if certainly_bad(spec[name], value):
                value_bad.append((opts[idx], "%s %r" % (name, value[:40])))
        elif idx is not None and opts[idx][1] is not None and name in spec and op < 0.55:
            value = spec[name].edge(rng)
            opts[idx] = (name, value)
            if certainly_bad(spec[name], value):
                value_bad.append((opts[idx], "%s %r" % (name, value[:40])))
        elif op < 0.62 and opts:
            del opts[idx]
        elif op < 0.70 and opts:
            value = spec[name].valid(rng) if name in spec else opts[idx][1]
            opts.insert(rng.randrange(len(opts) + 1), (name, value))
        elif op < 0.77 and opts and name.startswith("--") and name != "--":
            opts[idx] = (name[1:], opts[idx][1])  # -height: must not be read as -h (help)
        elif op < 0.82 and opts and opts[idx][1] is not None:
            opts[idx] = (name + "=" + opts[idx][1], None)  # valid syntax, the value glued on
        elif op < 0.85 and spec:
            name = rng.choice(sorted(spec))
            opts.append((name, spec[name].valid(rng)))  # a valid option the base left out (maybe a conflict)
        elif op < 0.98:
            opts.append((rng.choice(STRAY_OPTIONS), rng.choice(["4", "", None])))
        else:
            opts.append((rng.choice(["--help", "-h"]), None))
    # Certainly bad as the list ends up (a later edit may have dropped or replaced an earlier one's subject).
    bad = [why for entry, why in value_bad if any(entry is o for o in opts)]
    names = [o.split("=", 1)[0] for o, _ in opts]
    for name in sorted(set(names)):
        if name == "--":
            continue
        if name.startswith("-") and not name.startswith("--") and len(name) > 2:
            bad.append("single-dash %s" % name)  # -height: must not be read as -h (help)
        elif name not in known:
            bad.append("unknown option %s" % name)
        elif names.count(name) > 1 and name not in multi and any(v is not None or "=" in o for o, v in opts
                                                                  if o.split("=", 1)[0] == name):
            bad.append("%s given twice" % name)  # "At Most 1" (CLI11); a flag given twice is still the flag
    knobs = [v.split("=", 1)[0] for o, v in opts if o == "--set" and v]
    if len(set(knobs)) < len(knobs):
        bad.append("--set of one knob twice")  # which value holds?
    return opts, bad


def draw(rng, spec, keys, required=()):
    """Valid values for the required keys and some of the others."""
    opts = [(k, spec[k].valid(rng)) for k in required]
    for k in keys:
        if k not in required and rng.random() < 0.3:
            opts.append((k, spec[k].valid(rng)))
    return opts


def wall_opts(rng, spec=WALL):
    return draw(rng, spec, sorted(spec), required=("--height", "--thickness", "--hinge"))


def motion_opts(rng, pulse_period_hi=1.0):
    if rng.random() < 0.5:
        opts = [("--record", RECORD.valid(rng)), ("--pga", MOTION_RECORD["--pga"].valid(rng))]
        return opts, dict(MOTION_RECORD)
    opts = [(k, MOTION_PULSE[k].valid(rng)) for k in MOTION_PULSE]
    return opts, dict(MOTION_PULSE)


def finish(rng, command, opts, spec, positional=(), json_flag=True, files=None, out_dirs=()):
    """The case with probability 0.3 valid as drawn, else mutated; --json added on most runs that take it."""
    bad, mutated = [], rng.random() >= 0.3
    if mutated:
        opts, bad = mutate(rng, opts, spec, command)
    if json_flag and rng.random() < 0.85 and "--json" not in [o for o, _ in opts]:
        opts.append(("--json", None))
    args = assemble(opts, positional)
    json_out = json_flag and "--json" in args and not helped(args) and "--list-settings" not in args
    return Case(command, command.split() + args, json_out=json_out, files=files, out_dirs=out_dirs,
                bad=[] if helped(args) else bad, valid=not mutated and valid_as_drawn(command, opts))


def valid_as_drawn(command, opts):
    """Whether an unmutated draw is valid input: the generators draw each option from its valid values, but a few
    draws combine into what the docs refuse (the paper's kinematics with the unilateral roller; a parapet has no
    roller or kinematics of a VSSW to choose; `--csv -` with `--json`) or into a run that may fail for a stated
    reason (an engine's compare measures metrics that may be unmeasurable, exit 3)."""
    given = dict((o, v) for o, v in opts)
    names = [o for o, _ in opts]
    if len(set(names)) < len(names):
        return False  # an option drawn twice (history's harmonic adds a second --pulse)
    if given.get("--csv") == "-":
        return False  # --json, added to most runs, writes to standard output too: refused
    if "--record" in given and "--pulse" in given:
        return False  # history's harmonic added beside a record: one ground motion at a time
    if "--strict" in given:
        return False  # a warning of the model's own checks (e.g. friction needed above 0.6) is exit 3 by design
    if given.get("--impact") == "1":
        return False  # elastic impacts: a free vibration never comes to rest (exit 3 with that reason)
    # The set's parts (default mechanism: exact kinematics, unilateral roller), each overridden when drawn.
    paper_set = given.get("--assumptions", "mechanism") == "paper"
    kinematics = given.get("--kinematics", "paper" if paper_set else "exact")
    roller = given.get("--roller", "bilateral" if paper_set else "unilateral")
    if roller == "unilateral" and kinematics == "paper" and given.get("--model") != "parapet":
        return False
    if given.get("--model") == "parapet" and any(k in given for k in ("--roller", "--kinematics", "--hinge")):
        return False
    # compare may measure nothing (exit 3); check may find a bound out (exit 1); describe draws odd paths on purpose.
    return command not in ("compare", "check", "motions describe")


def helped(args):
    """Whether the user asked for help or for compare's settings listing (an early output like --help: the words
    around it go unchecked, as CLI11 does for --help: exit 0)."""
    return any(a in ("-h", "--help", "--list-settings") or a.startswith("--help=") for a in args)


# `vssw wall` takes the geometry alone (no model, kinematics, impact or roller).
GEOMETRY = {k: v for k, v in WALL.items() if k in ("--height", "--thickness", "--hinge", "--xi", "--density", "--g")}


def gen_wall(rng):
    return finish(rng, "wall", wall_opts(rng, GEOMETRY), dict(GEOMETRY))


def gen_free(rng):
    spec = dict(WALL)
    spec.update({"--theta0": Num(0.1, 0.9, edges=(0.0, 1.0)), "--rtol": Num(1e-10, 1e-6, log=True, edges=(1e-14, 1.0)),
                 "--output-dt": Num(1e-3, 1e-2, log=True, edges=(1e-9, 10.0)),
                 "--csv": Out(CSV_FILES + ["-"], ODD_OUTS)})
    opts = wall_opts(rng) + [("--theta0", spec["--theta0"].valid(rng))]
    if rng.random() < 0.3:
        opts.append(("--csv", spec["--csv"].valid(rng)))
    if rng.random() < 0.1:
        opts.append(("--strict", None))
    return finish(rng, "free", opts, spec)


def gen_history(rng):
    spec = dict(WALL)
    motion, motion_spec = motion_opts(rng)
    spec.update(motion_spec)
    spec.update({"--t-end": Num(0.5, 3.0, edges=(0.0, 1e7)), "--output-dt": Num(1e-3, 1e-2, log=True, edges=(1e-9, 10.0)),
                 "--csv": Out(CSV_FILES + ["-"], ODD_OUTS), "--record-dt": Num(0.005, 0.02, edges=(1e-310, 1e3)),
                 "--vertical-record": RECORD, "--duration": Num(0.5, 2.0, edges=(0.0, 1e7)),
                 "--time-column": Word(["t", "time"]), "--accel-column": Word(["a", "acc"])})
    opts = wall_opts(rng) + motion + [("--t-end", spec["--t-end"].valid(rng))]
    if rng.random() < 0.3:
        opts.append(("--csv", spec["--csv"].valid(rng)))
    if rng.random() < 0.1:
        opts += [("--pulse", "harmonic"), ("--duration", spec["--duration"].valid(rng))]
    return finish(rng, "history", opts, spec)


def gen_summary(rng):
    spec = {"--record": RECORD}
    opts = [("--record", RECORD.valid(rng))] if rng.random() < 0.7 else []
    return finish(rng, "summary", opts, spec)


# Engines drawn for compare: mostly the cheap ones (analytic, ODE, Bullet: 0.1-0.5 s a run), now and then Simbody or
# Siconos (0.6-2.5 s).
CHEAP_ENGINES = ["analytic", "ode", "bullet", "analytic", "ode", "bullet", "siconos", "simbody"]
# Engine settings by engine (`vssw compare --list-settings`), with the extremes the findings met.
KNOBS = {
    "ode": ["erp", "cfm", "margin", "surface_layer", "max_correcting_vel", "quickstep", "slide_limit"],
    "bullet": ["erp", "moving_supports", "slide_limit", "penetration_limit"],
    "analytic": ["rtol", "restitution", "paper_kinematics"],
    "siconos": ["e_ground", "theta", "gamma", "tolerance"],
    "simbody": ["stiffness", "dissipation", "accuracy", "transition_velocity"],
}
KNOB_VALUES = ["0", "1", "0.5", "0.2", "1e-300", "1e-310", "1e300", "1e308", "-1e308", "2", "3", "nan", "", "-0"]
# Knob values that crashed or hung a run before (ODE's margin aborted the process, Simbody's creep velocity never
# ended): drawn often, so that a fixed seed meets them.
KNOB_FINDINGS = {"ode": ["margin=1e308", "margin=1e300"], "simbody": ["transition_velocity=1e-300"],
                 "bullet": ["erp=1e308"], "analytic": ["rtol=1e-300"], "siconos": ["tolerance=1e-300"]}


def gen_compare(rng):
    engine = rng.choice(CHEAP_ENGINES)
    spec = dict(WALL)
    spec.update({
        "--engine": Word(["analytic", "ode", "bullet"], listy=True),
        "--theta0": Num(0.2, 0.8, edges=(0.01, 1.0)),
        "--dt": Num(2e-4, 2e-3, log=True, edges=(1e-9, 1e3)),
        "--iterations": Num(5, 50, integer=True, edges=(1, 1000)),
        "--set": Word([f"{k}={v}" for k in KNOBS[engine] for v in KNOB_VALUES[:4]]),
    })
    opts = [("--engine", engine)] + wall_opts(rng)
    if rng.random() < 0.5:
        motion, motion_spec = motion_opts(rng)
        spec.update(motion_spec)
        # Records are long (20-40 s); an engine on a whole record takes seconds: the pulse is the short excitation.
        if motion[0][0] == "--record" and engine not in ("analytic", "ode"):
            motion = [(k, MOTION_PULSE[k].valid(rng)) for k in MOTION_PULSE]
            spec.update(MOTION_PULSE)
        opts += motion
    if rng.random() < 0.3:
        opts.append(("--set", f"{rng.choice(KNOBS[engine])}={rng.choice(KNOB_VALUES)}"))
    elif rng.random() < 0.15:
        opts.append(("--set", rng.choice(KNOB_FINDINGS[engine])))
    if rng.random() < 0.05:
        opts.append(("--list-settings", None))
    return finish(rng, "compare", opts, spec)


# The default suite's cheapest cases (one threshold each, one free vibration): report and check stay under a second.
SUITE_CASES = ["fig6-vssw", "fig6-pw", "fig6-vssw/r0.5", "fig6-pw/r0.5"]


def suite_file(rng):
    """A small suite file (a study of named parts) for `report --suite`, its wall name at times a shell command."""
    name = rng.choice(["w1", "w1`cd;touch PWNED8`", "w$(cd;touch PWNED9)", "w'q\"", "w\u00e9", "w1\n!cd;touch PWNED10"])
    return ('name = "mini"\nengines = ["analytic", "ode"]\n[[part]]\nwall_name = %s\n[part.wall]\nheight = 4.0\n'
            'thickness = 0.4\nhinge = 0.7\n[part.excitation]\nkind = "free"\ntheta0 = 0.5\n' % toml_value(name))


def gen_report(rng):
    spec = {"--suite": Word(["default", "suite.toml"]), "--engines": Word(["analytic", "ode", "bullet"], listy=True),
            "--cases": Word(SUITE_CASES, listy=True), "--threads": Num(1, 2, integer=True, edges=(0, 256)),
            "--out": Out(OUT_DIRS, ODD_OUTS), "--data": Path(["data"], ODD_INPUT_PATHS)}
    files = {"suite.toml": suite_file(rng)}
    opts = [("--out", rng.choice(OUT_DIRS)), ("--engines", spec["--engines"].valid(rng))]
    if rng.random() < 0.4:
        opts += [("--suite", "default"), ("--cases", spec["--cases"].valid(rng))]
    else:
        opts.append(("--suite", "suite.toml"))
    if rng.random() < 0.5:
        opts.append(("--no-plots", None))  # plots run gnuplot: the names reach its scripts (kept on half the runs)
    return finish(rng, "report", opts, spec, json_flag=False, files=files)


def bounds_file(rng, fmt):
    """A small bounds file: analytic entries of the default suite's cheap cases, an engine entry, values at times
    extreme (a bad bound must be refused, a tight one may fail: exit 1)."""
    value = lambda good: good if rng.random() < 0.8 else rng.choice(["nan", "inf", "-1", "0", "1e308", "\"x\"", "[]"])
    entries = [("analytic", {"case": "\"fig6-vssw\"", "metric": "\"threshold_g\"", "reference": value("0.2857"),
                             "max_drift": value(rng.choice(["0.0002", "1e-12"]))})]
    if rng.random() < 0.5:
        entries.append(("engine", {"engine": "\"%s\"" % rng.choice(["ode", "bullet", "odee", ""]),
                                   "cases": "[\"fig6-vssw\"%s]" % rng.choice(["", ", \"fig6-vssw\"", ", \"\""]),
                                   "metric": "\"threshold_g\"", "max_error": value("0.005")}))
    if fmt == "toml":
        text = 'suite = "default"\n' + "".join(
            "[[%s]]\n" % kind + "".join("%s = %s\n" % kv for kv in e.items()) for kind, e in entries)
    else:
        groups = {}
        for kind, e in entries:
            groups.setdefault(kind, []).append("{" + ", ".join('"%s": %s' % kv for kv in e.items()) + "}")
        text = '{"suite": "default", ' + ", ".join('"%s": [%s]' % (k, ", ".join(v)) for k, v in groups.items()) + "}"
    return text


def gen_check(rng):
    fmt = rng.choice(["toml", "json"])
    name = "bounds." + fmt
    spec = {"--bounds": Path([name], ODD_INPUT_PATHS + ["rec.AT2", "bounds.txt"]),
            "--threads": Num(1, 2, integer=True, edges=(0, 256)), "--data": Path(["data"], ODD_INPUT_PATHS)}
    opts = [("--bounds", name)]
    return finish(rng, "check", opts, spec, files={name: bounds_file(rng, fmt), "bounds.txt": "x = 1\n"})


# The quick stress set's cases that finish in a fraction of a second on the analytic model and ODE.
STRESS_CASES = ["xi-50", "hinge-0.05", "squat-t/h0.5", "release-1e-6-alpha", "step-10x"]


def gen_stress(rng):
    spec = {"--cases": Word(STRESS_CASES, listy=True), "--engines": Word(["analytic", "ode"], listy=True),
            "--time-limit": Num(5, 20, edges=(0.0, 3600.0)), "--threads": Num(1, 2, integer=True, edges=(0, 256)),
            "--out": Out(OUT_DIRS, ODD_OUTS)}
    opts = [("--cases", spec["--cases"].valid(rng)), ("--engines", spec["--engines"].valid(rng)),
            ("--time-limit", spec["--time-limit"].valid(rng))]
    if rng.random() < 0.5:
        opts.append(("--out", rng.choice(OUT_DIRS)))
    return finish(rng, "stress", opts, spec)


def gen_bench(rng):
    spec = {"--problems": Word(["fig6-free", "pw-free"], listy=True), "--engines": Word(["analytic", "ode"], listy=True),
            "--repeats": Num(1, 2, integer=True, edges=(1, 100)), "--out": Out(OUT_DIRS, ODD_OUTS),
            "--data": Path(["data"], ODD_INPUT_PATHS)}
    opts = [("--quick", None), ("--out", rng.choice(OUT_DIRS)), ("--problems", spec["--problems"].valid(rng)),
            ("--engines", spec["--engines"].valid(rng)), ("--repeats", "1")]
    if rng.random() < 0.8:
        opts.append(("--no-plots", None))
    return finish(rng, "bench", opts, spec)


# --- study files ---------------------------------------------------------------------------------------------------


def toml_value(v):
    """A Python value as TOML: floats as repr (nan, inf, 1e+308 are TOML), strings as basic strings."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v) if not (isinstance(v, float) and math.isnan(v)) else "nan"
    if isinstance(v, str):
        out = '"'
        for ch in v:
            if ch in '"\\':
                out += "\\" + ch
            elif ord(ch) < 0x20 or ord(ch) == 0x7F:
                out += "\\u%04X" % ord(ch)
            else:
                out += ch
        return out + '"'
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join("%s = %s" % (toml_key(k), toml_value(x)) for k, x in v.items()) + "}"
    raise TypeError(v)


def toml_key(k):
    return k if k and all(c.isascii() and (c.isalnum() or c in "-_") for c in k) else toml_value(k)


def to_toml(doc):
    """A study document as TOML: scalars and lists first, then tables, then arrays of tables ([[part]])."""
    lines = []

    def emit(table, prefix):
        for k, v in table.items():
            if not isinstance(v, dict) and not (isinstance(v, list) and v and all(isinstance(x, dict) for x in v)):
                lines.append("%s = %s" % (toml_key(k), toml_value(v)))
        for k, v in table.items():
            if isinstance(v, dict):
                lines.append("[%s]" % ".".join(prefix + [toml_key(k)]))
                emit(v, prefix + [toml_key(k)])
        for k, v in table.items():
            if isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
                for item in v:
                    lines.append("[[%s]]" % ".".join(prefix + [toml_key(k)]))
                    emit(item, prefix + [toml_key(k)])

    emit(doc, [])
    return "\n".join(lines) + "\n"


def levels(rng, valid, n_max=2):
    """A scalar or a list of 1..n_max distinct valid values."""
    n = rng.choice([1, 1, 1, 2, n_max])
    if n == 1 and rng.random() < 0.7:
        return valid()
    out = []
    for _ in range(n * 3):
        v = valid()
        if v not in out:
            out.append(v)
        if len(out) == n:
            break
    return out


def study_doc(rng):
    """A valid small study (seconds at most): a wall grid of at most a few cases, one excitation, cheap engines."""
    r3 = lambda lo, hi: round(rng.uniform(lo, hi), 3)
    kind = rng.choice(["closed-form", "threshold", "free", "free", "pulse", "record", "record", "scale-to-collapse"])
    route = rng.choice(["ht", "ht", "aR", "a12", "specimen"])
    wall = {}
    if route == "ht":
        wall.update(height=levels(rng, lambda: r3(2.0, 5.0)), thickness=levels(rng, lambda: r3(0.2, 0.5)))
    elif route == "aR":
        wall.update(alpha=levels(rng, lambda: r3(0.05, 0.2)), R=levels(rng, lambda: r3(0.5, 3.0)))
    elif route == "a12":
        wall.update(alpha1=r3(0.08, 0.15), alpha2=r3(0.08, 0.15), R1=r3(0.5, 2.0))
    else:
        wall.update(specimen=levels(rng, lambda: rng.choice([1, 7, 15])))
    if route in ("ht", "aR") or (route == "specimen" and rng.random() < 0.3):
        wall["hinge"] = levels(rng, lambda: rng.choice([r3(0.4, 0.9), "eq15"]))
    if rng.random() < 0.4:
        wall["xi"] = levels(rng, lambda: r3(0.0, 0.3))
    if route in ("ht", "aR") and rng.random() < 0.2:
        wall["model"] = "parapet"
        wall.pop("hinge", None)
    doc = {"name": rng.choice(["s", "study-%d" % rng.randrange(100)])}
    engines = ["analytic"]
    if kind in ("threshold", "free", "pulse") and rng.random() < 0.4:
        engines.append(rng.choice(["ode", "bullet", "ode", "siconos"]))
    if kind == "closed-form":
        doc["metrics"] = rng.sample(["threshold_closed_form_g", "restitution_closed_form", "period_linearised"], 2)
        ex = {"kind": kind, "theta0": r3(0.1, 0.8)}
    elif kind == "threshold":
        ex = {"kind": kind}
    elif kind == "free":
        ex = {"kind": kind, "theta0": levels(rng, lambda: r3(0.1, 0.8))}
    elif kind == "pulse":
        ex = {"kind": kind, "shape": levels(rng, lambda: rng.choice(["sine", "cosine", "ricker"])),
              "amplitude": levels(rng, lambda: r3(0.2, 1.0)), "pulse_period": r3(0.2, 0.8)}
    elif kind == "record":
        # Now and then a record under a name a shell or gnuplot would run (the plots' titles hold it).
        files = ["rec.AT2", "elc.txt"] * 4 + ODD_RECORD_NAMES[:5]
        ex = {"kind": kind, "file": rng.choice(files), "pga": levels(rng, lambda: r3(0.1, 0.4))}
    else:
        # Coarse steps and tolerance: a handful of whole-record runs instead of hundreds.
        ex = {"kind": kind, "file": "elc.txt", "step": 0.5, "tolerance": 0.1, "max_pga": 1.0}
    doc["engines"] = engines
    if rng.random() < 0.3:
        kinematics = levels(rng, lambda: rng.choice(["paper", "exact"]))
        doc["assumptions"] = {"kinematics": kinematics,
                              "impact": levels(rng, lambda: rng.choice(["eq19", "whole-mechanism", 0.5]))}
        if rng.random() < 0.7:
            # The paper's kinematics need the set paper's bilateral roller (the default set's roller only pushes).
            paper = "paper" in (kinematics if isinstance(kinematics, list) else [kinematics])
            doc["assumptions"]["set"] = "paper" if paper else rng.choice(["paper", "mechanism"])
    if len(engines) > 1 and rng.random() < 0.5:
        doc["settings"] = {engines[1]: {"dt": rng.choice([1e-3, 2e-3])}}
    doc["wall"], doc["excitation"] = wall, ex
    return doc


# Values a broken study file puts in place of a valid one (the study file's counterparts of EXTREME_NUMBERS).
STUDY_EXTREMES = [
    "", 0, -0.0, -1, 1e-310, 1e308, -1e308, float("nan"), float("inf"), -float("inf"), 2 ** 63 - 1, 10 ** 30,
    "\u0664", "4", [], [[]], {}, [0.5, 0.5], [0.6, 0.6000000000000001], [0.0, -0.0], True, None,
    "x" * 5000, "`cd;touch PWNED4`", "$(cd;touch PWNED5)", "a\"b'c", "line\nbreak", "\u00e9", "eq15",
    "missing.AT2", "adir", "/dev/zero", "r`cd;touch PWNED1`.AT2", "r\n!cd;touch PWNED3\n.AT2",
]


def _bad_value(v):
    """A value no key of a study file takes: an empty list or table, a list of one empty list, NaN or infinity, a list
    with a repeated value (0.0 and -0.0 are one value)."""
    if isinstance(v, float) and not math.isfinite(v):
        return True
    return v in ([], [[]], {}, [0.5, 0.5], [0.0, -0.0]) and not isinstance(v, bool)


def break_study(rng, doc):
    """1-2 edits that make a study file wrong, or extreme but maybe valid: a value replaced, a key dropped or added,
    a list emptied or given a repeated value, a harmonic of many cycles, an engine's knob at its extreme. Returns the
    document and why it is certainly bad (empty when it may be valid)."""
    bad = {}  # root key of the edit -> reason; a later edit to the same root replaces it

    def note(root, reason):
        for r in [r for r in bad if r == root]:
            del bad[r]
        if reason:
            bad[root] = reason

    for _ in range(rng.choice([1, 1, 2])):
        tables = [("doc", doc)] + [(k, doc[k]) for k in ("wall", "excitation") if isinstance(doc.get(k), dict)]
        tname, table = rng.choice(tables)
        keys = list(table)
        op = rng.random()
        if op < 0.40 and keys:
            k = rng.choice(keys)
            v = rng.choice(STUDY_EXTREMES)
            root = k if tname == "doc" else tname
            if v is None:
                del table[k]
                note(root, None)
            else:
                table[k] = v
                note(root, "%s.%s = %r" % (tname, k, v) if _bad_value(v) else None)
        elif op < 0.50 and keys:
            k = rng.choice(keys)
            del table[k]
            note(k if tname == "doc" else tname, None)
        elif op < 0.58:
            k = rng.choice(["unknown", "Height", "wall", "kind", "metrics", "pga", "file", "theta0", ""])
            table[k] = 1.0
            note(k if tname == "doc" else tname, "unknown key %r in %s" % (k, tname)
                 if k in ("unknown", "Height", "") else None)
        elif op < 0.66:
            duration = rng.choice([1.0, 1e7, 2e6, 1e308, 0.0])
            doc["excitation"] = {"kind": "pulse", "shape": "harmonic", "amplitude": 0.3, "pulse_period": 0.5,
                                 "duration": duration}
            # More than 1e6 cycles of 0.5 s, or no duration: refused by `vssw history`, so by a study too.
            note("excitation", "harmonic duration %r" % duration if duration != 1.0 else None)
        elif op < 0.78:
            engine = rng.choice(["ode", "bullet", "simbody", "analytic"])
            knob = rng.choice(KNOBS[engine] + ["dt", "iterations", "nope"])
            value = rng.choice([0, 1e-300, 1e300, 1e308, -1.0, 1e-9, 1e3, 0.5, [1.0, 1.0]])
            engines = doc.get("engines") if isinstance(doc.get("engines"), list) else ["analytic"]
            doc["engines"] = sorted(set(x for x in engines if isinstance(x, str)) | {engine})
            doc["settings"] = {engine: {knob: value}}
            why = None
            if knob == "nope" or value == [1.0, 1.0]:
                why = "setting %s.%s = %r" % (engine, knob, value)
            elif engine == "analytic" and knob in ("dt", "iterations", "restitution", "paper_kinematics"):
                why = "analytic %s" % knob  # no step or iterations; its assumptions go in [assumptions]
            elif knob == "dt" and value in (0, -1.0):
                why = "dt %r" % value
            elif knob == "iterations" and value not in (1e3,):
                why = "iterations %r" % value  # an integer from 1 to 1000
            note("engines", None)
            note("settings", why)
        elif op < 0.86:
            key = rng.choice(["impact", "kinematics", "roller", "set", "x"])
            value = rng.choice([0, 1, 1.0, 0.0, -0.0, 1.5, "eq19", "", ["eq19", "eq19"], "exact", "paper",
                                ["paper", "mechanism"]])
            doc["assumptions"] = {key: value}
            words = {"impact": ("eq19", "whole-mechanism"), "kinematics": ("paper", "exact"),
                     "roller": ("bilateral", "unilateral"), "set": ("paper", "mechanism")}.get(key, ())
            ok = key == "impact" and isinstance(value, (int, float)) and 0 <= value <= 1 or value in words
            note("assumptions", None if ok else "assumptions.%s = %r" % (key, value))
        elif op < 0.93:
            metrics = rng.choice([[], ["period", "period"], ["nope"], ["threshold_g", ""], "period",
                                  ["collapse_scale"], ["peak_rotation"]])
            doc["metrics"] = metrics
            note("metrics", None if metrics in (["collapse_scale"], ["peak_rotation"]) else "metrics %r" % metrics)
        else:
            engines = rng.choice([[], ["ode", "ode"], ["analytic", ""], ["all"], "ode", {}, {"ode": {}},
                                  ["analytic", "simbody-rigid"]])
            doc["engines"] = engines
            note("engines", None if engines in ({"ode": {}}, ["analytic", "simbody-rigid"]) else "engines %r" % engines)
    return doc, sorted(bad.values())


# Files that are not a study at all, or barely: empty, syntax errors, binary, deep nesting, a long line.
RAW_STUDY_TEXTS = [
    "", "\n", "name = \n", "[wall\n", "name = \"s\"\n[wall]\nheight = 4\nheight = 5\n", "\x00\x01\x02garbage",
    "a = " + "[" * 300 + "]" * 300 + "\n", "{" * 100000, "name = \"" + "x" * 100000 + "\"\n", "\ufeffname = \"s\"\n",
    "[[part]]\n" * 50, "{\"name\": \"s\", \"name\": \"t\"}", "[1, 2, 3]", "null", "\"just a string\"",
]


def gen_study(rng):
    fmt = rng.choice(["toml", "toml", "json"])
    name = "study." + fmt
    out = rng.choice(OUT_DIRS)
    roll = rng.random()
    records, file_bad = [], []
    if roll < 0.1:
        text = rng.choice(RAW_STUDY_TEXTS)
        file_bad = ["not a study file"]
    else:
        doc = study_doc(rng)
        if rng.random() < 0.08:
            # A study whose output folder holds its own inputs: a record named results.csv, the file results.json.
            doc["excitation"] = {"kind": "record", "file": "results.csv", "pga": 0.2}
            fmt, name, out = "json", rng.choice(["results.json", "study.json"]), "."
        elif roll >= 0.5:
            doc, file_bad = break_study(rng, doc)
        text = to_toml(doc) if fmt == "toml" else json.dumps(doc, ensure_ascii=rng.random() < 0.5)
        ex = doc.get("excitation")
        files = ex.get("file") if isinstance(ex, dict) else None
        records = [f for f in (files if isinstance(files, list) else [files]) if isinstance(f, str) and f]
    spec = {"--out": Out(OUT_DIRS, ODD_OUTS + [name, "rec.AT2"]), "--threads": Num(1, 2, integer=True, edges=(0, 256)),
            "--shard": Word(["1/1", "1/2", "2/2"]), "--resume": None, "--force": None, "--strict": None}
    opts = [("--out", out), ("--threads", spec["--threads"].valid(rng))]
    if rng.random() < 0.7:
        opts.append(("--no-plots", None))  # plots run gnuplot on the file and record names (kept on 3 in 10)
    for flag in ("--resume", "--force", "--strict"):
        if rng.random() < 0.1:
            opts.append((flag, None))
    if rng.random() < 0.1:
        opts.append(("--shard", spec["--shard"].valid(rng)))
    spec = {k: v for k, v in spec.items() if v is not None}
    positional = [name] if rng.random() < 0.95 else [rng.choice(ODD_INPUT_PATHS + ["study.yaml"])]
    # Mutated less often than options: the file's content is the subject here.
    bad = list(file_bad)
    if rng.random() < 0.25:
        opts, more = mutate(rng, opts, spec, "study")
        bad += more
    if rng.random() < 0.8 and "--json" not in [o for o, _ in opts]:
        opts.append(("--json", None))
    args = ["study"] + assemble(opts, positional)
    if positional[0] != name:
        bad = [b for b in bad if b not in file_bad]  # the file is not read
    outs = tuple(v for k, v in opts if k == "--out" and v)
    return Case("study", args, json_out="--json" in args and not helped(args), files={name: text}, out_dirs=outs,
                inputs=[name] + [r for r in records if len(r) < 255], bad=[] if helped(args) else bad)


def gen_study_merge(rng):
    """study merge on shards of a small study (made once, see shards()), on shards with a part missing or given
    twice, on folders that are not shards."""
    dirs = rng.choice([["sh1", "sh2"], ["sh2", "sh1"], ["sh1"], ["sh1", "sh1"], ["sh1", "sh2", "sh2"], ["sh1", "adir"],
                       ["sh1", "missing"], ["sh1", "sh2cut"], ["sh1", "rec.AT2"], [], ["sh1", "sh2", "out"],
                       ["sh1", ""], ["sh1", "sh2/"]])
    out = rng.choice(OUT_DIRS + ["sh1", "", "rec.AT2"])
    opts = [("--out", out)] if rng.random() < 0.95 else []
    if rng.random() < 0.8:
        opts.append(("--no-plots", None))
    if rng.random() < 0.8:
        opts.append(("--json", None))
    args = ["study", "merge"] + dirs + assemble(opts)
    return Case("study merge", args, json_out="--json" in args, out_dirs=tuple(v for k, v in opts if k == "--out"))


def gen_motions_generate(rng):
    """A few synthetic motions (fractions of a second each); the edges stay small enough to write in seconds."""
    spec = {"--count": Num(1, 3, integer=True, edges=(0, 3)), "--seed": Num(0, 1000, integer=True, edges=(0, 1e19)),
            "--out": Out(OUT_DIRS, ODD_OUTS), "--dt": Num(0.005, 0.02, edges=(0.001, 0.1)),
            "--duration": Num(5.0, 20.0, edges=(0.0, 100.0)), "--scatter": Num(0.0, 1.0, edges=(0.0, 2.0)),
            "--d5-95": Num(5.0, 20.0, edges=(5.0, 45.0)), "--damping": Num(0.05, 0.5, edges=(0.02, 0.95)),
            "--mechanism": Word(["strike-slip", "reverse"])}
    opts = [("--count", spec["--count"].valid(rng)), ("--seed", spec["--seed"].valid(rng)),
            ("--out", rng.choice(OUT_DIRS)), ("--duration", spec["--duration"].valid(rng))]
    for key in ("--dt", "--scatter", "--d5-95", "--damping"):
        if rng.random() < 0.3:
            opts.append((key, spec[key].valid(rng)))
    return finish(rng, "motions generate", opts, spec, json_flag=True)


def gen_motions_describe(rng):
    """Any record the readers take, and odd paths: one line naming a bad one, exit 2."""
    files = rng.sample(RECORDS + ODD_INPUT_PATHS, rng.randint(1, 3))
    spec = {}
    opts = [rng.choice([("--csv", None), ("--json", None)])] if rng.random() < 0.6 else []
    return finish(rng, "motions describe", opts, spec, positional=files, json_flag=False)


GENERATORS = {
    "wall": gen_wall, "free": gen_free, "history": gen_history, "summary": gen_summary, "compare": gen_compare,
    "report": gen_report, "check": gen_check, "study": gen_study, "study merge": gen_study_merge,
    "stress": gen_stress, "bench": gen_bench, "motions generate": gen_motions_generate,
    "motions describe": gen_motions_describe,
    # The surface added since (tests/cli/property_surface.py).
    "study ensemble": lambda rng: surface.gen_ensemble_study(rng, Case, to_toml),
    "plugins": lambda rng: surface.gen_plugins(rng, Case, VSSW),
    "hostile names": lambda rng: surface.gen_hostile_names(rng, Case),
}
# Cases of these commands: fewer where one run costs more (report, check, stress, bench: 0.2-1 s each and little
# option surface beyond the others'), more for study files (the file is a large input space of its own).
CASE_SHARE = {"report": 0.5, "check": 0.5, "stress": 0.5, "bench": 0.4, "study merge": 0.5, "study": 2.0,
              "summary": 0.5, "study ensemble": 0.7, "plugins": 0.5, "hostile names": 0.7}


# --- running -------------------------------------------------------------------------------------------------------


def snapshot(root):
    """Every entry under root (not following links): path -> (kind, size, mtime_ns, content hash)."""
    snap = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames + filenames:
            p = os.path.join(dirpath, name)
            st = os.lstat(p)
            rel = os.path.relpath(p, root)
            if os.path.isdir(p) and not os.path.islink(p):
                snap[rel] = ("dir", 0, 0, "")
                continue
            digest = ""
            if os.path.isfile(p) and not os.path.islink(p) and st.st_size <= HASH_LIMIT_BYTES:
                with open(p, "rb") as f:
                    digest = hashlib.sha1(f.read()).hexdigest()
            snap[rel] = ("file", st.st_size, st.st_mtime_ns, digest)
    return snap


def output_paths(args):
    """The values of --out and --csv as given (--opt VALUE or --opt=VALUE), "-" (standard output) left out."""
    outs = []
    for i, a in enumerate(args):
        if a in ("--out", "--csv") and i + 1 < len(args):
            outs.append(args[i + 1])
        elif a.startswith("--out=") or a.startswith("--csv="):
            outs.append(a.split("=", 1)[1])
    return [o for o in outs if o not in ("", "-")]


def allowed(rel, outputs, is_dir=False):
    """Whether a path relative to the run's folder lies in one of its outputs (itself or inside it), or is a folder
    on the way to one (--out out2/sub makes out2); --out . allows the whole folder (its inputs stay protected)."""
    rel = os.path.normpath(rel)
    for out in outputs:
        o = os.path.normpath(out)
        if o == "." or rel == o or rel.startswith(o + os.sep) or (is_dir and o.startswith(rel + os.sep)):
            return True
    return False


def input_paths(args, folder, extra):
    """What the run reads: every argument naming an existing path in its folder (but the values of --out and --csv),
    and the files a study file names (extra); normalised."""
    inputs, skip = set(os.path.normpath(e) for e in extra), False
    for i, a in enumerate(args):
        if skip:
            skip = False
            continue
        if a in ("--out", "--csv"):
            skip = True
            continue
        if a.startswith("--out=") or a.startswith("--csv="):
            continue
        value = a.split("=", 1)[1] if a.startswith("--") and "=" in a else a
        if value and not os.path.isabs(value) and len(value) < 255 and os.path.lexists(os.path.join(folder, value)):
            inputs.add(os.path.normpath(value))
    return inputs


def make_inputs(folder, shards_dir):
    """The run's folder: copies of the records under plain and odd names, a folder, an empty file, junk, data/."""
    os.makedirs(folder)
    for name in RECORDS:
        src = "elcentro_chopra.txt" if name in ("elc.txt", "results.csv") else "NGA_no_1063_RRS228.AT2"
        shutil.copyfile(os.path.join(DATA, src), os.path.join(folder, name))
    os.makedirs(os.path.join(folder, "adir"))
    open(os.path.join(folder, "empty.txt"), "w").close()
    with open(os.path.join(folder, "junk.bin"), "wb") as f:
        f.write(bytes(range(256)) * 4)
    shutil.copytree(DATA, os.path.join(folder, "data"))
    if shards_dir:
        for d in os.listdir(shards_dir):
            shutil.copytree(os.path.join(shards_dir, d), os.path.join(folder, d))


# What a message must never carry raw: C0 controls but the line break and tab, DEL, and C1 (ESC's 8-bit forms).
CONTROL_BYTES = re.compile("[\x00-\x08\x0b-\x1f\x7f\x80-\x9f]")

NON_FINITE_STRINGS = {"nan", "-nan", "+nan", "inf", "-inf", "+inf", "infinity", "-infinity"}


def non_finite(value, where="$"):
    """The first NaN or infinity in a parsed JSON value (a number, or a string that is one), as a JSON path."""
    if isinstance(value, float) and not math.isfinite(value):
        return where
    if isinstance(value, str) and value.strip().lower() in NON_FINITE_STRINGS:
        return where
    if isinstance(value, dict):
        for k, v in value.items():
            hit = non_finite(v, "%s.%s" % (where, k))
            if hit:
                return hit
    if isinstance(value, list):
        for i, v in enumerate(value):
            hit = non_finite(v, "%s[%d]" % (where, i))
            if hit:
                return hit
    return None


def parse_json(text):
    """JSON as Python's json reads it, but NaN/Infinity tokens (not JSON) are kept as floats to be reported."""
    return json.loads(text, parse_constant=lambda token: float(token.replace("Infinity", "inf")))


def run_case(case, work, shards_dir):
    """Runs one case in its own folder; returns a list of (class, detail) broken promises (empty: kept)."""
    folder = os.path.join(work, "run-%s-%03d" % (case.command.replace(" ", "-"), case.index))
    make_inputs(folder, shards_dir if case.command == "study merge" else None)
    for name, text in case.files.items():
        with open(os.path.join(folder, name), "w", encoding="utf-8", errors="surrogatepass") as f:
            f.write(text)
    if case.setup:
        case.setup(folder)
    before = snapshot(folder)
    out_existed = {o: os.path.exists(os.path.join(folder, o)) for o in case.out_dirs}
    env = dict(os.environ, HOME=folder, LC_ALL="C.UTF-8", **case.env)
    env.pop("VSSW_DATA_DIR", None)  # the program finds its data itself; --data is what the case gives
    start = time.monotonic()
    proc = subprocess.Popen([VSSW] + case.args, cwd=folder, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True)
    try:
        stdout, stderr = proc.communicate(timeout=RUN_TIMEOUT_S)
        timed_out = False
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)  # the run's own process group: it and any worker it forked
        stdout, stderr = proc.communicate()
        timed_out = True
    elapsed = time.monotonic() - start
    rc = proc.returncode
    out_text = stdout.decode("utf-8", "replace")
    err_lines = [l for l in stderr.decode("utf-8", "replace").splitlines()]
    broken = []
    allowed_codes = {0, 1, 2, 3} if case.command == "check" else {0, 2, 3}
    if timed_out:
        broken.append(("hang", "killed after %d s" % RUN_TIMEOUT_S))
    elif rc < 0:
        broken.append(("signal", "killed by %s" % signal.Signals(-rc).name))
    elif rc not in allowed_codes:
        broken.append(("exit code %d" % rc, "not one of %s" % sorted(allowed_codes)))
    elif rc == 2:
        if len(err_lines) != 1 or not err_lines[0].startswith("vssw: error:"):
            broken.append(("exit 2 without exactly one 'vssw: error:' line", "%d stderr lines" % len(err_lines)))
    elif rc == 3:
        if not any(l.startswith("vssw: simulation failed:") and len(l) > 25 for l in err_lines):
            broken.append(("exit 3 without a 'vssw: simulation failed:' reason", ""))
    elif rc == 1:
        if not any(l.startswith("vssw: check failed:") for l in err_lines):
            broken.append(("exit 1 without a 'vssw: check failed:' line", ""))
    elif rc == 0 and case.json_out:
        try:
            hit = non_finite(parse_json(out_text))
            if hit:
                broken.append(("NaN or infinity in JSON output", hit))
        except ValueError as e:
            broken.append(("exit 0 with --json but no JSON on stdout (help printed?)", str(e)[:80]))
    outputs = output_paths(case.args)
    inputs = input_paths(case.args, folder, case.inputs)
    after = snapshot(folder)
    for rel in sorted(set(before) | set(after)):
        if before.get(rel) == after.get(rel):
            continue
        is_dir = (after.get(rel) or before.get(rel))[0] == "dir"
        if rel in before and (rel in inputs or any(rel.startswith(i + os.sep) for i in inputs)):
            broken.append(("an input file changed or removed", rel))
        elif rel in before and not allowed(rel, outputs, is_dir):
            broken.append(("a file changed or removed outside --out/--csv", rel))
        elif rel not in before and not allowed(rel, outputs, is_dir):
            broken.append(("a file created outside --out/--csv", rel))
    if rc == 0:
        for rel in sorted(after):
            if rel.endswith(".json") and rel not in before and after[rel][0] == "file" and after[rel][3]:
                try:
                    with open(os.path.join(folder, rel), encoding="utf-8") as f:
                        hit = non_finite(parse_json(f.read()))
                    if hit:
                        broken.append(("NaN or infinity in a written .json file", "%s %s" % (rel, hit)))
                except ValueError as e:
                    broken.append(("a written .json file is not JSON", "%s: %s" % (rel, str(e)[:60])))
    if case.bad and not timed_out and rc >= 0 and rc != 2:
        broken.append(("certainly bad input not refused (exit %d)" % rc, "; ".join(case.bad)))
    if rc == 2:
        for o, existed in out_existed.items():
            if not existed and os.path.lexists(os.path.join(folder, o)):
                broken.append(("exit 2 left a new --out folder (refused after the work, or not before it)", o))
    if case.valid and not timed_out and rc != 0:
        broken.append(("valid input did not succeed (exit %d)" % rc, "valid as drawn"))
    control = sorted(set(CONTROL_BYTES.findall(stderr.decode("utf-8", "surrogateescape"))))
    if control:
        broken.append(("a control character reached the terminal", " ".join("%r" % c for c in control)))
    # One entry per class and run: a shell command run from a name may create a dozen files.
    merged = {}
    for cls, detail in broken:
        merged.setdefault(cls, []).append(detail)
    broken = [(cls, ", ".join(repr(d) if "file" in cls else d for d in details[:3]) +
               (" and %d more" % (len(details) - 3) if len(details) > 3 else "")) for cls, details in merged.items()]
    result = {"case": case, "rc": rc, "elapsed": elapsed, "broken": broken, "folder": folder,
              "stderr1": err_lines[0][:200] if err_lines else ""}
    if VERBOSE:
        print("%s exit %s %.2fs %s | %s" % ("FAIL" if broken else "ok", rc, elapsed, case.line()[:300],
                                             result["stderr1"]))
    if not broken:
        shutil.rmtree(folder, ignore_errors=True)
    return result


@pytest.fixture(scope="module")
def work():
    root = os.environ.get("VSSW_PROPERTY_WORK")
    if root:
        shutil.rmtree(root, ignore_errors=True)
        os.makedirs(root)
    else:
        root = tempfile.mkdtemp(prefix="vssw-cli-properties-")
    yield root
    if not os.listdir(root):
        shutil.rmtree(root, ignore_errors=True)


@pytest.fixture(scope="module")
def shards(work):
    """Shards 1/2 and 2/2 of a small analytic study, made once, and a damaged copy of the second (rows cut)."""
    folder = os.path.join(work, "shards")
    os.makedirs(folder)
    with open(os.path.join(folder, "s.toml"), "w") as f:
        f.write('name = "m"\nmetrics = ["threshold_closed_form_g"]\n[wall]\nheight = [3.0, 4.0, 5.0]\n'
                'thickness = 0.4\nhinge = [0.6, 0.7]\n[excitation]\nkind = "closed-form"\n')
    made = os.path.join(work, "shard-dirs")
    os.makedirs(made)
    for k in (1, 2):
        subprocess.run([VSSW, "study", "s.toml", "--out", os.path.join(made, "sh%d" % k), "--shard", "%d/2" % k,
                        "--no-plots"], cwd=folder, check=True, capture_output=True, timeout=RUN_TIMEOUT_S)
    shutil.copytree(os.path.join(made, "sh2"), os.path.join(made, "sh2cut"))
    results = os.path.join(made, "sh2cut", "results.csv")
    with open(results) as f:
        rows = f.read().splitlines(True)
    with open(results, "w") as f:
        f.writelines(rows[:2])
    shutil.rmtree(folder)
    yield made
    shutil.rmtree(made, ignore_errors=True)


def test_the_program_is_there():
    assert os.access(VSSW, os.X_OK), "VSSW_EXECUTABLE=%s is not an executable" % VSSW
    assert os.path.isfile(os.path.join(DATA, "NGA_no_1063_RRS228.AT2")), "VSSW_DATA_DIR=%s has no records" % DATA


@pytest.mark.parametrize("command", list(GENERATORS))
def test_every_run_keeps_the_promise(command, work, shards):
    rng = random.Random("%d:%s" % (SEED, command))  # a string seed: the same sample on every Python and machine
    n = max(1, round(CASES * CASE_SHARE.get(command, 1.0)))
    cases = []
    for i in range(n):
        case = GENERATORS[command](rng)
        case.index = i
        cases.append(case)
    with concurrent.futures.ThreadPoolExecutor(max_workers=JOBS) as pool:
        results = list(pool.map(lambda c: run_case(c, work, shards), cases))
    failures = [r for r in results if r["broken"]]
    codes = sorted(r["rc"] for r in results)
    summary = "%s: %d runs, exit codes %s, %.1f s of runs" % (
        command, len(results), {c: codes.count(c) for c in set(codes)}, sum(r["elapsed"] for r in results))
    print(summary)
    if not failures:
        return
    by_class = {}
    for r in failures:
        for cls, detail in r["broken"]:
            by_class.setdefault(cls, []).append((r, detail))
    lines = [summary, "seed %d (VSSW_PROPERTY_SEED); failing runs' folders kept under %s" % (SEED, work)]
    for cls, items in sorted(by_class.items()):
        lines.append("")
        lines.append("== %s: %d run(s)" % (cls, len(items)))
        for r, detail in items:
            case = r["case"]
            lines.append("  exit %s in %.1f s%s | stderr: %s" % (r["rc"], r["elapsed"], " | " + detail if detail else "",
                                                                 r["stderr1"] or "(empty)"))
            lines.append("    cd %s && HOME=$PWD %s" % (shlex.quote(r["folder"]), case.line()))
            for name, text in case.files.items():
                if name in case.args:  # the generated file the run read (study, suite or bounds file)
                    lines.append("    %s: %r" % (name, text[:SHOW_FILE_CHARS]))
    pytest.fail("\n".join(lines), pytrace=False)
