#!/usr/bin/python3
"""Where an engine run's CPU goes: inside the engine library or outside it (docs/measurements/speed.md, "The floor
and the adapters").

Runs one `vssw` command N times under `perf record --call-graph dwarf` (perf: `bash scripts/setup.sh profile`) and
sorts the samples of the forked child that runs the engine (multibody/host/isolated_engine.hpp) by their call stacks:
  engine   a frame in one of the engine library's shared objects (its step, its collision, its set-up);
  contacts no such frame, a frame of the contact generation an adapter does for its engine each step (ODE's
           OdeScene::add_pair and add_roller: dCollide's points merged into contact joints, the roller's row;
           Bullet's CornerContacts::update: the corners' and the roller's manifolds): the engine's contact scheme,
           like the floor's own contact finding (bench/floor/), done outside the library;
  plugin   no such frame, a frame in the adapter's plugin: the adapter and the kit it links (scene set-up, the hooks,
           sampling, the run monitor, the energy sum);
  kernel   the leaf in the kernel: the fresh child's page faults, its exit;
  loader   the dynamic loader: symbols bound lazily in each child;
  other    the rest: the harness's code in the child (the trajectory's bytes to the pipe) and stacks perf could not
           unwind.
It prints the shares of the children's samples, and of the whole command's, then the engine's entry points and the
plugin's functions by share; `--leaves N` adds the N commonest functions the plugin's samples were taken in (the C
library's atan2 or a page fault below an adapter's hook, where the plugin's functions name only the hook).

    bench/adapter_share.py --runs 20 -- build/vssw free --engine ode --height 4 --thickness 0.4 --hinge 0.7 --theta0 0.5
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

# The shared objects of the engine libraries and of what they link (ldd of each plugin in build/plugins/, less the
# C and C++ runtimes, which adapter and engine share and are sorted by their callers).
ENGINE = re.compile(r"libode|libccd|libBullet|libLinearMath|libbox2d|libmujoco|libdart|libfcl|liboctom|libassimp|"
                    r"liburdf|libtinyxml|libSimTK|libsiconos|libopenblas|libblas|liblapack|libgfortran|libmumps|"
                    r"libdmumps|libcxsparse|libqhull|liblodepng|libboost|libconsole_bridge")
# The adapters' contact generation for their engines (kept out of line so that a profile sees it).
CONTACTS = re.compile(r"OdeScene::add_pair|OdeScene::add_roller|CornerContacts::update")
FORK = re.compile(r"\s*vssw\s+\d+/\d+\s+PERF_RECORD_FORK\((\d+):\d+\):\((\d+):\d+\)")
FRAME = re.compile(r"\s*[0-9a-f]+ (.*) \((.*)\)$")


def clean(symbol):
    return re.sub(r"\(.*", "", symbol.replace("(anonymous namespace)::", ""))


def samples(lines, forked):
    """(pid, frames leaf first) of each sample of a vssw process; the pids of its forked children into `forked`."""
    head, frames = None, []
    for line in lines:
        m = FORK.match(line)
        if m:
            if m.group(1) != m.group(2):  # a process, not a thread
                forked.add(m.group(1))
            continue
        if "PERF_RECORD" in line:
            continue
        if not line.strip():
            if head and head[0] == "vssw":
                yield head[1].split("/")[0], frames
            head, frames = None, []
        elif not line.startswith(("\t", " ")):
            head, frames = line.split(), []
        else:
            m = FRAME.match(line)
            if m:
                frames.append((m.group(1), m.group(2)))
    if head and head[0] == "vssw":
        yield head[1].split("/")[0], frames


def bucket(frames):
    dsos = [d for _, d in frames]
    if any(ENGINE.search(d) for d in dsos):
        return "engine"
    if any("vssw_engine_" in d and CONTACTS.search(s) for s, d in frames):
        return "contacts"
    if any("vssw_engine_" in d for d in dsos):
        return "plugin"
    if dsos and "kernel" in dsos[0]:
        return "kernel"
    if any("ld-linux" in d for d in dsos):
        return "loader"
    return "other"


def engine_entry(frames):
    """The outermost engine frame: the engine function the adapter called."""
    return next((clean(s) for s, d in reversed(frames) if ENGINE.search(d)), "")


def plugin_function(frames):
    """The innermost plugin frame: the adapter's or the kit's function the sample is in."""
    return next((clean(s) for s, d in frames if "vssw_engine_" in d), "")


def leaf(frames):
    """The function the sample was taken in, and its shared object."""
    return f"{clean(frames[0][0])} [{os.path.basename(frames[0][1])}]" if frames else ""


def record(command, runs, frequency):
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        data = os.path.join(tmp, "perf.data")
        for _ in range(runs):
            subprocess.run(["perf", "record", "-q", "-F", str(frequency), "--call-graph", "dwarf,32768", "-o", data,
                            "--"] + command, check=True, stdout=subprocess.DEVNULL)
            script = subprocess.run(["perf", "script", "-i", data, "--show-task-events", "-F",
                                     "comm,pid,tid,ip,sym,dso"], check=True, capture_output=True, text=True)
            forked = set()
            rows += [(pid in forked, frames) for pid, frames in samples(script.stdout.splitlines(), forked)]
    return rows


def shares(rows):
    counts = collections.Counter(bucket(f) for f in rows)
    n = max(sum(counts.values()), 1)
    return f"{sum(counts.values())} samples: " + ", ".join(f"{k} {100.0 * v / n:.1f} %" for k, v in counts.most_common())


def top(rows, key, title, n, count=10):
    print(title)
    for name, v in collections.Counter(key(f) for f in rows).most_common(count):
        if name:
            print(f"  {100.0 * v / n:5.1f} %  {name[:100]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=10, help="how many times to run the command (default 10)")
    parser.add_argument("--frequency", type=int, default=2999, help="perf's sampling rate [Hz] (default 2999)")
    parser.add_argument("--leaves", type=int, default=0,
                        help="also list this many functions the plugin's samples were taken in (default 0)")
    parser.add_argument("command", nargs=argparse.REMAINDER, help="-- then the vssw command")
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command or args.runs < 1 or args.frequency < 1 or args.leaves < 0:
        parser.error("give --runs >= 1, --frequency >= 1, --leaves >= 0 and a command after --")
    rows = record(command, args.runs, args.frequency)
    children = [f for in_child, f in rows if in_child]
    print("the runs (forked children): " + shares(children))
    print("the whole commands: " + shares([f for _, f in rows]))
    n = max(len(children), 1)
    top([f for f in children if bucket(f) == "engine"], engine_entry, "engine entry points (share of the runs):", n)
    top([f for f in children if bucket(f) == "plugin"], plugin_function, "in the plugin (share of the runs):", n)
    if args.leaves:
        top([f for f in children if bucket(f) == "plugin"], leaf, "the plugin's samples taken in (share of the runs):",
            n, args.leaves)
    return 0


if __name__ == "__main__":
    sys.exit(main())
