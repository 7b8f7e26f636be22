"""The closed forms and free vibration through the module, against physics the paper states, so that the module is
checked for what it returns and not only for agreeing with the program."""
import math

import numpy as np
import pytest

import vssw
from conftest import FIG6

# Computed closed forms compared across sizes: only rounding differs (a few ulps of each of a dozen operations).
CLOSED_FORM_RTOL = 1e-12
# Free vibration's event times and peaks from +theta0 and -theta0: the integrator (rtol 1e-10 by default) follows
# mirror-image paths with the same steps, so they agree far below its tolerance; 1e-9 leaves room for rounding.
MIRROR_RTOL = 1e-9



@pytest.mark.parametrize("scale", [0.01, 0.5, 3.0, 100.0])
def test_threshold_and_restitution_do_not_depend_on_size(scale):
    # Eq. (12) and Eq. (19) depend on the angles alone (and on xi): all lengths scaled, the angles stay.
    base = vssw.wall(**FIG6, xi=0.2)
    scaled = vssw.wall(height=4.0 * scale, thickness=0.4 * scale, hinge=0.7, xi=0.2)
    for key in ["threshold_g", "restitution", "alpha1", "alpha2"]:
        assert scaled[key] == pytest.approx(base[key], rel=CLOSED_FORM_RTOL), key
    # Lengths scale with the wall, the linearised period (Eq. 22, ~ 1/p, p ~ 1/sqrt(R)) as the square root.
    assert scaled["R1"] == pytest.approx(base["R1"] * scale, rel=CLOSED_FORM_RTOL)
    assert scaled["period_half_A"] == pytest.approx(base["period_half_A"] * math.sqrt(scale), rel=CLOSED_FORM_RTOL)


def test_parapet_is_housners_block():
    # Housner (1963): alpha = atan(b/h), e = 1 - 3/2 sin^2 alpha, threshold tan(alpha) g, p^2 = 3 g / (4 R).
    height, thickness, g = 0.9, 0.11, 9.81
    parapet = vssw.wall(height=height, thickness=thickness, hinge=0.5, g=g)["parapet"]
    alpha = math.atan(thickness / height)
    radius = math.hypot(thickness, height) / 2
    assert parapet["alpha"] == pytest.approx(alpha, rel=CLOSED_FORM_RTOL)
    assert parapet["R"] == pytest.approx(radius, rel=CLOSED_FORM_RTOL)
    assert parapet["restitution"] == pytest.approx(1 - 1.5 * math.sin(alpha) ** 2, rel=CLOSED_FORM_RTOL)
    assert parapet["threshold_g"] == pytest.approx(math.tan(alpha), rel=CLOSED_FORM_RTOL)
    assert parapet["p"] == pytest.approx(math.sqrt(3 * g / (4 * radius)), rel=CLOSED_FORM_RTOL)


@pytest.mark.parametrize("assumptions", ["paper", "mechanism"])
def test_free_vibration_from_minus_theta0_mirrors_plus_theta0(assumptions):
    plus = vssw.free(**FIG6, theta0=0.6, assumptions=assumptions)
    minus = vssw.free(**FIG6, theta0=-0.6, assumptions=assumptions)
    assert len(plus["impacts"]) == len(minus["impacts"]) > 0
    assert minus["first_impact_time"] == pytest.approx(plus["first_impact_time"], rel=MIRROR_RTOL)
    assert minus["peaks"] == pytest.approx(plus["peaks"], rel=MIRROR_RTOL)  # |theta|/alpha: the same magnitudes
    for p, m in zip(plus["impacts"], minus["impacts"]):
        assert m["t"] == pytest.approx(p["t"], rel=MIRROR_RTOL)
        assert m["theta_dot_before"] == pytest.approx(-p["theta_dot_before"], rel=MIRROR_RTOL)  # mirrored velocity


def eq19_as_printed(height, thickness, hinge):
    """Eq. (19) transcribed from the paper (its tan(alpha2)/tan(alpha1), not the code's k), for homogeneous blocks:
    I_G = m R^2 / 3 about each centroid; masses per unit depth and density cancel."""
    b, h = thickness / 2, height / 2
    h1 = hinge * h
    h2 = h - h1
    a1, a2 = math.atan(b / h1), math.atan(b / h2)
    R1, R2 = math.hypot(b, h1), math.hypot(b, h2)
    m1, m2 = 4 * b * h1, 4 * b * h2
    I1, I2 = m1 * R1**2 / 3, m2 * R2**2 / 3
    ratio = math.tan(a2) / math.tan(a1)
    s1, c1 = math.sin(a1), math.cos(a1)
    common = m1 * R1**2 + I1 - I2 * ratio
    num = common - 2 * m1 * R1**2 * s1**2 + m2 * R1**2 * (2 + s1 * c1 / math.tan(a2) - s1**2 * (4 + ratio))
    den = common + m2 * R1**2 * (2 + s1 * c1 * (1 / math.tan(a2) + math.tan(a2)))
    return num / den


def test_restitution_is_eq19_as_printed():
    # The module's closed form against an independent transcription of the paper's Eq. (19), on three walls.
    for wall in [FIG6, dict(height=3.0, thickness=0.143, hinge=0.6), dict(height=6.0, thickness=0.25, hinge=0.5)]:
        assert vssw.wall(**wall)["restitution"] == pytest.approx(eq19_as_printed(**wall), rel=CLOSED_FORM_RTOL), wall


def test_free_vibration_first_impact_follows_the_impact_law():
    # theta1' after / before the first impact is the impact law's ratio: Eq. (19) by default, or a given e. The
    # impact law scales the velocity by the ratio directly, so CLOSED_FORM_RTOL (rounding) holds here too.
    eq19 = eq19_as_printed(**FIG6)
    for impact, expected in [("eq19", eq19), (0.6, 0.6)]:
        first = vssw.free(**FIG6, theta0=0.5, impact=impact)["impacts"][0]
        assert first["theta_dot_after"] / first["theta_dot_before"] == pytest.approx(expected, rel=CLOSED_FORM_RTOL)


# A slide in m and in b (the CLI's JSON gives both) are one division and one multiplication apart: rounding only.
SLIP_UNITS_RTOL = 4 * np.finfo(float).eps


# Finite friction (docs/model/analytic-core.md "Finite friction"): the Fig. 6 parapet under a sine pulse of 3 times
# its threshold slides before it rocks below tan(alpha) = 0.1 and lifts first above it; at the default friction no slip
# is measured (None) and the same pulse rocks it.
@pytest.mark.skipif("ode" not in vssw.engines(), reason="no ODE in this build")
def test_friction_given_measures_sliding_below_tan_alpha():
    parapet = dict(model="parapet", height=4.0, thickness=0.4)
    pulse = dict(pulse="sine", amplitude=0.3, pulse_period=0.5, t_end=2.0)
    slid = vssw.simulate("ode", **parapet, **pulse, friction=0.08).slip
    held = vssw.simulate("ode", **parapet, **pulse, friction=0.12).slip
    slid_limit = 5e-2  # in b: the default friction's failure limit; measured 0.27 b below tan(alpha)
    assert slid.slid_before_rocking and slid.t_first_lift is None
    assert slid.base.largest_b > slid_limit
    assert slid.base.largest_m == pytest.approx(slid.base.largest_b * slid.b, rel=SLIP_UNITS_RTOL)
    assert slid.hinge is None  # a parapet has no hinge
    assert held.t_first_lift is not None and not held.slid_before_rocking
    with pytest.warns(FutureWarning, match="slip.base.largest_m"):  # the flat dict's keys, read with a warning
        assert slid["base_largest"] == slid.base.largest_m
    assert vssw.simulate("ode", **parapet, **pulse).slip is None
