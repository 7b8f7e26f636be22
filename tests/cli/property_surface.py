"""The property test's cases on the surface added since its first version (tests/cli/test_cli_properties.py runs
them): ensemble studies, engine plugins found through VSSW_PLUGIN_PATH, and hostile bytes in names (bytes that are
not UTF-8, terminal control sequences). Each generator returns a Case of test_cli_properties; what a run must do is
checked there, the same for every command.

A case builds its inputs with `setup(folder)` (symlinks, FIFOs, damaged plugins: what a text file cannot hold) and
names what is certainly bad about it (`bad`: then it must exit 2), or is `valid` as drawn (then it must exit 0).
"""

import os
import shutil

# Bytes that are not UTF-8 (0xff, a lone continuation byte, an overlong '/'), as Python passes them in argv and
# paths: os.fsdecode maps each to a lone surrogate, which subprocess and open() turn back into the byte.
NON_UTF8 = [os.fsdecode(b) for b in (b"\xff", b"\x80", b"\xc0\xaf")]
# Terminal control: ESC sequences that set the window title and clear the screen, a bell, a backspace, C1's CSI.
CONTROL = ["\x1b]0;PWNED\x07", "\x1b[2J", "\x07", "\x08", "\x9b31m"]


def hostile_name(rng, stem, suffix=""):
    """A file or folder name carrying a non-UTF-8 byte or a control sequence."""
    return stem + rng.choice(NON_UTF8 + CONTROL) + suffix


# --- ensembles ------------------------------------------------------------------------------------------------------

# The run's folder holds rec.AT2 (Rinaldi) and elc.txt (El Centro, two columns); ens/ holds two AT2 copies.
ENSEMBLE_LEVELS = [[0.3], [0.3, 0.5], [0.25, 0.4, 0.6]]


def ensemble_doc(rng, how):
    """A small valid ensemble study of the Fig. 6 wall: two records, one or a few PGA levels or an IDA."""
    doc = {"name": "e", "metrics": ["peak_rotation", "overturned"], "engines": ["analytic"],
           "wall": {"height": 4.0, "thickness": 0.4, "hinge": 0.7},
           "assumptions": {"kinematics": "exact", "impact": "whole-mechanism", "roller": "unilateral"}}
    ex = {"kind": "ensemble", "intensity": "pga"}
    if how == "files":
        ex["files"] = ["ens/a.at2", "ens/b.at2"]
    else:
        ex["ensemble"] = "ens"
    if rng.random() < 0.7:
        ex["levels"] = rng.choice(ENSEMBLE_LEVELS)
        if rng.random() < 0.3:
            ex["band"] = True
    else:
        ex.update(collapse=True, max_pga=1.5, step=0.5, tolerance=0.1)
        doc["metrics"] = ["collapse_scale", "collapse_pga"]
    doc["excitation"] = ex
    return doc


def ensemble_folder(folder, extra=None):
    """ens/ with two AT2 records (copies of rec.AT2 under two names), and what `extra` adds to it."""
    ens = os.path.join(folder, "ens")
    os.makedirs(ens, exist_ok=True)
    for name in ("a.at2", "b.at2"):
        shutil.copyfile(os.path.join(folder, "rec.AT2"), os.path.join(ens, name))
    if extra:
        extra(ens)


# What an ensemble folder may hold that is no record it can read: each certainly bad (the study names it, exit 2).
def _dangling(ens):
    os.symlink("missing.at2", os.path.join(ens, "x.at2"))


def _loop(ens):
    os.symlink("x.at2", os.path.join(ens, "x.at2"))


def _fifo(ens):
    os.mkfifo(os.path.join(ens, "x.at2"))


def _device(ens):
    os.symlink("/dev/zero", os.path.join(ens, "x.at2"))


def _folder(ens):
    os.makedirs(os.path.join(ens, "x.at2"))


def _alias(ens):
    os.symlink("a.at2", os.path.join(ens, "c.at2"))  # one record under a second name: counted twice


BROKEN_FOLDERS = {"a dangling symlink": _dangling, "a symlink loop": _loop, "a FIFO": _fifo,
                  "a device": _device, "a folder": _folder, "a symlink alias of a record": _alias}
# One record spelled twice in a files list (the same file, not a copy).
SAME_FILE_TWICE = [["ens/a.at2", "ens/./a.at2"], ["ens/a.at2", "ens/../ens/a.at2"], ["ens/a.at2", "enslink/a.at2"]]


def gen_ensemble_study(rng, case_class, to_toml):
    """An ensemble study: valid, or with a broken folder entry or one record under two spellings."""
    how = rng.choice(["files", "dir"])
    doc = ensemble_doc(rng, how)
    roll = rng.random()
    extra, bad = None, []
    if roll < 0.25 and how == "dir":
        why, extra = rng.choice(sorted(BROKEN_FOLDERS.items()))
        bad = ["ensemble folder holds %s" % why]
    elif roll < 0.40 and how == "files":
        doc["excitation"]["files"] = rng.choice(SAME_FILE_TWICE)
        bad = ["one record twice: %s" % doc["excitation"]["files"]]
    elif roll < 0.50:
        doc["excitation"]["levels" if "levels" in doc["excitation"] else "max_pga"] = rng.choice(
            [[1e308], [0.3, 1e308], 1e308] if "levels" in doc["excitation"] else [1e-310, 0.1])
        bad = ["a level no record can be scaled to, or a ceiling below the wall's threshold"]

    def setup(folder):
        ensemble_folder(folder, extra)
        os.symlink("ens", os.path.join(folder, "enslink"))

    args = ["study", "e.toml", "--out", "out", "--no-plots", "--json"]
    return case_class("study ensemble", args, json_out=True, files={"e.toml": to_toml(doc)}, out_dirs=("out",),
                      inputs=["e.toml", "ens"], bad=bad, valid=not bad and roll >= 0.5, setup=setup)


# --- plugins --------------------------------------------------------------------------------------------------------

def plugin_dir(vssw):
    """The build's plugins, beside the program (CMake's build/plugins)."""
    return os.path.join(os.path.dirname(vssw), "plugins")


def _cut_at(n_bytes=None, fraction=None):
    """A copy of the plugin cut short, as a copy or install that stopped halfway leaves it."""
    def make(src, dst):
        with open(src, "rb") as f, open(dst, "wb") as g:
            data = f.read()
            g.write(data[:n_bytes if n_bytes is not None else int(len(data) * fraction)])
    return make


def _plugin_symlink(target):
    def make(src, dst):
        os.symlink(target, dst)
    return make


def _plugin_folder(src, dst):
    os.makedirs(dst)


def _plugin_text(src, dst):
    with open(dst, "w") as f:
        f.write("not a shared object\n")


# A damaged ODE plugin where the user points VSSW_PLUGIN_PATH: each must be refused (exit 2; --version names it as
# not available and exits 0), never a signal, never another folder's plugin used instead.
DAMAGED_PLUGINS = {
    "cut at 4 KiB": _cut_at(n_bytes=4096), "cut at half": _cut_at(fraction=0.5),
    "cut at a tenth": _cut_at(fraction=0.1), "a dangling symlink": _plugin_symlink("/nowhere/vssw_engine_ode.so"),
    "a symlink loop": _plugin_symlink("vssw_engine_ode.so"), "a folder": _plugin_folder, "a text file": _plugin_text,
    "a symlink to /dev/zero": _plugin_symlink("/dev/zero"),
}


FIG6 = ["--height", "4", "--thickness", "0.4", "--hinge", "0.7"]
PULSE = ["--pulse", "sine", "--amplitude", "0.5", "--pulse-period", "0.5"]


def gen_plugins(rng, case_class, vssw):
    """A command that loads the ODE plugin from a folder the user points to, the plugin whole or damaged."""
    damage = rng.choice(sorted(DAMAGED_PLUGINS) + ["whole", "whole"])
    command = rng.choice([["--version"], ["compare", "--engine", "ode"] + FIG6 + ["--json"],
                          ["compare", "--engine", "ode"] + FIG6 + PULSE + ["--json"],
                          ["compare", "--engine", "ode", "--list-settings"]])
    src = os.path.join(plugin_dir(vssw), "vssw_engine_ode.so")

    def setup(folder):
        mine = os.path.join(folder, "plugins")
        os.makedirs(mine)
        dst = os.path.join(mine, "vssw_engine_ode.so")
        if damage == "whole":
            shutil.copyfile(src, dst)
        else:
            DAMAGED_PLUGINS[damage](src, dst)

    bad = [] if damage == "whole" or command == ["--version"] else ["the ODE plugin is %s" % damage]
    return case_class("plugins", command, json_out="--json" in command, bad=bad, valid=not bad, setup=setup,
                      env={"VSSW_PLUGIN_PATH": "plugins"})


# --- hostile bytes in names -----------------------------------------------------------------------------------------

def gen_hostile_names(rng, case_class):
    """A record, a study file, an --out folder or a motions folder whose name holds a non-UTF-8 byte or a control
    sequence, with --json on: a clear refusal up front or the right answer, never exit 2 after the work, and no
    control byte on the terminal (checked for every case in test_cli_properties.run_case)."""
    kind = rng.choice(["record", "study file", "study out", "motions out", "describe", "engine", "study key"])
    files, setup, out_dirs, inputs = {}, None, (), []
    if kind == "record":
        name = hostile_name(rng, "r", ".AT2")
        args = ["history", "--record", name, "--pga", "0.3"] + FIG6 + ["--json"]

        def setup(folder):
            shutil.copyfile(os.path.join(folder, "rec.AT2"), os.path.join(folder, name))
        inputs = [name]
    elif kind in ("study file", "study out"):
        text = ('name = "s"\nmetrics = ["threshold_closed_form_g"]\n[wall]\nheight = [3.0, 4.0]\nthickness = 0.4\n'
                'hinge = 0.7\n[excitation]\nkind = "closed-form"\n')
        study = hostile_name(rng, "s", ".toml") if kind == "study file" else "s.toml"
        out = hostile_name(rng, "o") if kind == "study out" else "out"
        files = {study: text}
        args = ["study", study, "--out", out, "--no-plots", "--json"]
        out_dirs, inputs = (out,), [study]
    elif kind == "motions out":
        out = hostile_name(rng, "m")
        args = ["motions", "generate", "--count", "1", "--seed", "1", "--duration", "5", "--out", out, "--json"]
        out_dirs = (out,)
    elif kind == "describe":
        name = hostile_name(rng, "d", ".AT2")
        args = ["motions", "describe", name, "--json"]

        def setup(folder):
            shutil.copyfile(os.path.join(folder, "rec.AT2"), os.path.join(folder, name))
        inputs = [name]
    elif kind == "engine":
        args = ["compare", "--engine", hostile_name(rng, "ode")] + FIG6
        return case_class("hostile names", args, bad=["an engine no build has"])
    else:
        key = "bad" + rng.choice(CONTROL)
        escaped = "".join(c if 0x20 <= ord(c) < 0x7f else "\\u%04x" % ord(c) for c in key)  # TOML's escapes
        text = ('name = "x"\nmetrics = ["period"]\n[wall]\nheight = 4.0\nthickness = 0.4\nhinge = 0.7\n'
                '"%s" = 1\n[excitation]\nkind = "free"\ntheta0 = 0.5\n' % escaped)
        return case_class("hostile names", ["study", "k.toml", "--out", "out", "--no-plots"], files={"k.toml": text},
                          out_dirs=("out",), inputs=["k.toml"], bad=["unknown key %r" % key])
    return case_class("hostile names", args, json_out="--json" in args, files=files, out_dirs=out_dirs,
                      inputs=inputs, setup=setup)
