#!/usr/bin/env python3
"""Write a bounds file for `vssw check` from a report's results.json (the headroom rules are printed at the top of
the file it writes). How bounds/default.toml and bounds/ci.toml were made:
    build/vssw report --suite default --out /tmp/rep
    python3 scripts/bounds_from_report.py /tmp/rep/results.json default > bounds/default.toml
    python3 scripts/bounds_from_report.py /tmp/rep/results.json ci > bounds/ci.toml
A maintainer's tool (Python 3 standard library only); neither the build nor the tests need it."""
import json, sys, collections
if len(sys.argv) != 3 or sys.argv[2] not in ('default', 'ci'):
    sys.exit('usage: bounds_from_report.py RESULTS_JSON default|ci')
d = json.load(open(sys.argv[1])); mode = sys.argv[2]
commit = d['vssw'].get('commit'); date = d['date']
TARGET = {'threshold_g': 0.005, 'period': 0.005, 'restitution': 0.02}
DRIFT = {'threshold_g': (2e-4, "one bisection bracket (1e-4) either side"),
         'period': (1e-5, "the integrator at rtol 1e-10 repeats to ~1e-9; a change of the model moves it far more"),
         'restitution': (1e-5, "first-impact ratio measured on the trajectory, as the period"),
         'peak_rotation': (1e-3, "a record's response amplifies round-off more than a free vibration"),
         'peak_time': (1e-3, "as the peak"),
         'overturned': (0.5, "0 or 1: absolute, any change fails")}
CI_ENGINE_CASES = {'fig6-vssw/r0.5', 'fig6-pw/r0.5', 't1-07-xi0.1/r0.5'}
rows = [r for r in d['rows'] if '/dt' not in r['case_id']]
out = []
def w(s=''): out.append(s)
w(f'# vssw check bounds: {"the CI subset" if mode=="ci" else "the default suite"}.')
w(f'# Measured by `vssw report --suite default` (vssw {commit}, {date[:10]}; reference: the analytic model under')
w(f'# the set {d.get("reference_assumptions", "mechanism")}), with headroom:')
w('#  - analytic: the stored value of each metric, max_drift relative (absolute for a 0 reference), per metric:')
for m,(x,why) in DRIFT.items(): w(f'#      {m}: {x:g} ({why})')
w('#  - engines: the relative error against the analytic model. Where every case is inside 0.8 x the project target')
w('#    (threshold 0.5 %, period 0.5 %, restitution 2 %), the bound is the target; a case outside it (a measured,')
w('#    explained difference, docs/engines.md) gets its own interval, the measured error +/- max(25 % of it, half')
w('#    the target), so that it fails if the difference grows, shrinks to nothing or changes sign.')
w('#  - history metrics of the engines (peak rotation under a record) have no target and are not bounded: rocking')
w('#    under a record is sensitive to every impact, the report shows them.')
if mode == 'ci':
    w('# The CI subset (tests/CMakeLists.txt: vssw_check_catches_a_broken_core): every analytic value, and the engines on')
    w('# ' + ', '.join(sorted(CI_ENGINE_CASES)) + ' (seconds).')
w('suite = "default"')
w()
for r in rows:
    if r['engine'] != 'analytic' or r['metric'] == 'rms_difference': continue
    x = r['engine_value']
    if x is None: continue
    w('[[analytic]]'); w(f'case = "{r["case_id"]}"'); w(f'metric = "{r["metric"]}"')
    w(f'reference = {x!r}'); w(f'max_drift = {DRIFT[r["metric"]][0]:g}'); w()
groups = collections.OrderedDict()
for r in rows:
    if r['engine'] == 'analytic' or r['metric'] not in TARGET: continue
    if mode == 'ci' and r['case_id'] not in CI_ENGINE_CASES: continue
    e = r['error']
    if e is None: continue
    t = TARGET[r['metric']]
    if abs(e) <= 0.8 * t:
        groups.setdefault((r['engine'], r['metric']), []).append(r['case_id'])
    else:
        h = max(0.25 * abs(e), 0.5 * t)
        w('[[engine]]'); w(f'engine = "{r["engine"]}"'); w(f'cases = ["{r["case_id"]}"]'); w(f'metric = "{r["metric"]}"')
        w(f'error = [{e - h:.4g}, {e + h:.4g}]  # measured {e:+.4g}'); w()
for (eng, m), cases in groups.items():
    w('[[engine]]'); w(f'engine = "{eng}"'); w('cases = [' + ', '.join(f'"{c}"' for c in cases) + ']')
    w(f'metric = "{m}"'); w(f'max_error = {TARGET[m]:g}'); w()
print('\n'.join(out))
