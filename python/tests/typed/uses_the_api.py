"""A user's script typed against vssw (checked by mypy in test_types.py, not run): each line states the type the
API's annotations must give, so that a wrong annotation fails the check."""
from typing import List, Optional

import numpy as np
import numpy.typing as npt

import vssw

run: vssw.Simulation = vssw.simulate("analytic", height=4.0, thickness=0.4, hinge=0.7, theta0=0.5, sample_dt=1e-3)
t: npt.NDArray[np.float64] = run.t
rotation: npt.NDArray[np.float64] = run.theta1_over_alpha1
alpha1: float = run.alpha1
period: Optional[float] = run.period
shaken: vssw.Simulation = vssw.simulate("ode", height=4.0, thickness=0.4, hinge=0.7,
                                        record=(0.01, np.zeros(100)), friction=0.5)
slip: Optional[vssw.Slip] = shaken.slip
if slip is not None and slip.hinge is not None:
    largest: float = slip.hinge.largest_m
one: vssw.Comparison = vssw.compare("ode", height=4.0, thickness=0.4, hinge=0.7)
error: float = one.threshold.rel_error
several: List[vssw.Comparison] = vssw.compare(["ode", "bullet"], height=4.0, thickness=0.4, hinge=0.7)
pair: List[vssw.Comparison] = vssw.compare(("ode", "bullet"), height=4.0, thickness=0.4, hinge=0.7)
every: List[vssw.Comparison] = vssw.compare("all", height=4.0, thickness=0.4, hinge=0.7)
names: List[str] = vssw.engines()
result: vssw.StudyResult = vssw.study({"name": "s"}, threads=2)
