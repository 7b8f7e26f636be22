"""Simulation.plot and Simulation.animate: what is drawn is the run (the plotted lines are its arrays, the drawn blocks
stand where the model's kinematics put them), written as asked, and bad requests are one clear InputError."""
import dataclasses
import subprocess
import sys

import numpy as np
import pytest

from conftest import FIG6

import vssw

# An animation only drawn frame by frame (draw_frame), never saved or shown, is what these tests make on purpose.
pytestmark = pytest.mark.filterwarnings("ignore:Animation was deleted without rendering")
matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the backend is chosen)

# Drawn coordinates [m] come from the same closed-form trigonometry as the model's own (two_block.hpp, Eq. 2), so they
# agree to round-off (~1e-15 m on a 4 m wall); 1e-9 m is far above that and far below the 0.1 mm slot the top can
# open off its roller, so a drawing that put the top anywhere but on the roller line would fail.
POSITION_TOLERANCE = 1e-9
# The exact kinematics with a roller that can also pull: the top never leaves the roller line, so the check is exact.
EXACT = dict(kinematics="exact", roller="bilateral")


@pytest.fixture(scope="module")
def release():
    return vssw.simulate("analytic", **FIG6, theta0=0.8, t_end=2.0, **EXACT)


def test_import_vssw_does_not_load_matplotlib():
    def loaded_after(code):
        done = subprocess.run([sys.executable, "-c", f"import sys, vssw; {code}; "
                               "print('matplotlib' in sys.modules)"], capture_output=True, text=True, check=True)
        return done.stdout.strip() == "True"

    assert not loaded_after("pass")
    # The check sees matplotlib once something loads it: a plot does.
    assert loaded_after("import matplotlib; matplotlib.use('Agg'); vssw.simulate('analytic', height=4, thickness=0.4, "
                        "hinge=0.7, theta0=0.5, t_end=0.1).plot()")


def test_the_plot_draws_the_runs_arrays_with_named_units(release):
    fig = release.plot()
    rotations, rise, energy = fig.axes
    theta1, theta2 = rotations.get_lines()
    np.testing.assert_array_equal(theta1.get_xdata(), release.t)
    np.testing.assert_array_equal(theta1.get_ydata(), release.theta1 / release.alpha1)
    np.testing.assert_array_equal(theta2.get_ydata(), release.theta2 / release.alpha1)
    np.testing.assert_array_equal(rise.get_lines()[0].get_ydata(), 1e3 * release.top_dy)
    np.testing.assert_array_equal(energy.get_lines()[0].get_ydata(), release.kinetic + release.potential)
    assert [ax.get_ylabel() for ax in fig.axes] == ["rotation / α1  [-]", "top's rise  [mm]", "energy  [J]"]
    assert energy.get_xlabel() == "t  [s]"
    plt.close(fig)


def test_plot_onto_given_axes_and_a_chosen_quantity(release):
    fig, ax = plt.subplots()
    assert release.plot(ax=ax, quantities="theta1") is fig
    assert len(ax.get_lines()) == 1 and ax.get_ylabel() == "θ1 / α1  [-]"
    plt.close(fig)


def test_a_parapet_plots_one_rotation_over_its_alpha():
    parapet = vssw.simulate("analytic", model="parapet", height=2.0, thickness=0.3, theta0=0.5, t_end=0.5)
    fig = parapet.plot(quantities=["theta1"])
    assert fig.axes[0].get_ylabel() == "θ / α  [-]"
    plt.close(fig)


@pytest.mark.parametrize("quantities, named", [("theta3", "'theta3'"), ([], "an empty list")])
def test_an_unknown_quantity_is_one_input_error(release, quantities, named):
    with pytest.raises(vssw.InputError, match=named):
        release.plot(quantities=quantities)


def test_without_matplotlib_plot_and_animate_say_what_to_install(release, monkeypatch):
    for module in ["matplotlib", "matplotlib.pyplot"]:
        monkeypatch.setitem(sys.modules, module, None)  # import of it fails, as where it is not installed
    for call in (release.plot, release.animate):
        with pytest.raises(vssw.InputError, match="python3-matplotlib"):
            call()


def drawn(anim, k):
    """Frame k as drawn: the lower and upper blocks' corners read back from the patches on the axes."""
    anim.draw_frame(k)
    blocks = anim.wall.blocks
    return blocks[0].get_xy()[:4], (blocks[1].get_xy()[:4] if len(blocks) > 1 else None)


def kinematics_errors(lower, upper, sim, i):
    """How far a drawing is from the run's sample i [m]: the base pivot off its corner of the ground, the lower block
    turned other than theta1 (its base's end beyond the pivot), the hinge not shared, the top corner off the roller
    line x = side b, and the top face's centre off the height top_dy gives. Corners counter-clockwise from the base
    corner at -x at rest."""
    g = sim.geometry
    b, height = g["b"], 2 * (g["h1"] + (g["h2"] or 0.0))
    side = 1 if sim.theta1[i] >= 0 else -1
    pivot, other = (lower[1], lower[0]) if side > 0 else (lower[0], lower[1])
    base_end = pivot + side * 2 * b * np.array([-np.cos(sim.theta1[i]), np.sin(sim.theta1[i])])
    top = upper if upper is not None else lower
    errors = {"pivot": np.linalg.norm(pivot - [side * b, 0.0]), "theta1": np.linalg.norm(other - base_end),
              "top rise": abs((top[2][1] + top[3][1]) / 2 - height - sim.top_dy[i])}
    if upper is not None:
        roller_corner = upper[2] if side > 0 else upper[3]
        hinge_on_lower, hinge_on_upper = (lower[3], upper[0]) if side > 0 else (lower[2], upper[1])
        errors["hinge"] = np.linalg.norm(hinge_on_lower - hinge_on_upper)
        errors["roller line"] = abs(roller_corner[0] - side * b)
    return errors


def test_the_drawn_blocks_stand_where_the_kinematics_put_them(release):
    anim = release.animate(fps=10)
    swung = [k for k, i in enumerate(anim.sample_indices) if abs(release.theta1[i]) > 0.3 * release.alpha1]
    assert any(release.theta1[anim.sample_indices[k]] < 0 for k in swung)  # both sides are checked
    assert any(release.theta1[anim.sample_indices[k]] > 0 for k in swung)
    for k in swung:
        errors = kinematics_errors(*drawn(anim, k), release, anim.sample_indices[k])
        assert max(errors.values()) < POSITION_TOLERANCE, (k, errors)
    # Each check fails a drawing that is wrong its way: the wall mirrored (turned about the other base corner), the
    # lower block turned 1 % too far, the upper block turned the wrong way, the upper block shifted off the hinge.
    k = swung[0]
    i = anim.sample_indices[k]
    wrongs = {"pivot": dict(theta1=-release.theta1, theta2=-release.theta2),
              "theta1": dict(theta1=1.01 * release.theta1),
              "roller line": dict(theta2=-release.theta2), "top rise": dict(theta2=-release.theta2)}
    for check, arrays in wrongs.items():
        errors = kinematics_errors(*drawn(dataclasses.replace(release, **arrays).animate(fps=10), k), release, i)
        assert errors[check] > POSITION_TOLERANCE, (check, errors)
    lower, upper = drawn(anim, k)
    assert kinematics_errors(lower, upper + [1e-3, 0.0], release, i)["hinge"] > POSITION_TOLERANCE
    plt.close("all")


def test_a_parapet_is_one_block_about_its_corner():
    parapet = vssw.simulate("analytic", model="parapet", height=2.0, thickness=0.3, theta0=0.8, t_end=1.0)
    anim = parapet.animate(fps=10)
    assert len(anim.wall.blocks) == 1
    for k, i in enumerate(anim.sample_indices):
        errors = kinematics_errors(*drawn(anim, k), parapet, i)
        assert max(errors.values()) < POSITION_TOLERANCE, (k, errors)
    plt.close("all")


def test_a_gif_has_one_frame_per_fps_th_of_a_second(release, tmp_path):
    from PIL import Image

    path = tmp_path / "wall.gif"
    fps, t_stop = 10, 0.4
    release.animate(path, fps=fps, t_stop=t_stop)
    with Image.open(path) as gif:
        assert gif.format == "GIF" and gif.n_frames == 5  # t = 0, 0.1, 0.2, 0.3, 0.4 s
    plt.close("all")


@pytest.mark.parametrize("path, named", [
    ("wall.avi", "written as .gif or .mp4, not '.avi'"),
    ("missing/wall.gif", "does not exist"),
])
def test_a_bad_path_is_one_input_error_and_writes_nothing(release, tmp_path, path, named):
    with pytest.raises(vssw.InputError, match=named) as raised:
        release.animate(tmp_path / path)
    assert "\n" not in str(raised.value)
    assert list(tmp_path.iterdir()) == []


def test_an_mp4_needs_ffmpeg(release, tmp_path):
    from matplotlib import animation

    if animation.writers.is_available("ffmpeg"):
        release.animate(tmp_path / "wall.mp4", fps=10, t_stop=0.2)
        assert (tmp_path / "wall.mp4").stat().st_size > 0
    else:
        with pytest.raises(vssw.InputError, match="needs ffmpeg"):
            release.animate(tmp_path / "wall.mp4")
        assert list(tmp_path.iterdir()) == []
    plt.close("all")


@pytest.mark.parametrize("arguments, named", [
    (dict(fps=0), "fps 0"), (dict(fps=500), "at most 100"), (dict(speed=-1.0), "speed -1.0"),
    (dict(t_start=1.0, t_stop=0.5), "t_start < t_stop"), (dict(t_stop=99.0), "span"),
])
def test_bad_frames_are_one_input_error(release, arguments, named):
    with pytest.raises(vssw.InputError, match=named):
        release.animate(**arguments)


# ODE holds its roller's corner on the guide and reports its top's rise to within 1e-4 m on this rounded wall (measured
# 8.6e-5 m and 1e-5 m); 2e-4 m is a tenth of the corner radius and 40 times below the 8.8e-3 m by which the same run
# drawn turning on sharp corners misplaces its top.
ENGINE_TOLERANCE = 2e-4


def test_a_rounded_wall_is_drawn_rolling_as_the_engine_moved_it():
    if "ode" not in vssw.engines():
        pytest.skip("ODE is not in this build")
    rounded = vssw.simulate("ode", **FIG6, theta0=0.8, t_end=2.0, corner_radius=0.1)
    anim = rounded.animate(fps=10)
    swung = [k for k, i in enumerate(anim.sample_indices) if abs(rounded.theta1[i]) > 0.3 * rounded.alpha1]
    assert len(anim.wall.blocks[0].get_xy()) > 4  # the corners drawn as arcs
    for k in swung:
        p = anim.draw_frame(k)
        i = anim.sample_indices[k]
        assert abs(p.roller_corner[0] - p.side * rounded.geometry["b"]) < ENGINE_TOLERANCE, k
        assert abs((p.upper[2][1] + p.upper[3][1]) / 2 - 4.0 - rounded.top_dy[i]) < ENGINE_TOLERANCE, k
    # The check fails the same run drawn turning on sharp corners.
    sharp = dataclasses.replace(rounded, geometry={**rounded.geometry, "corner_radius": 0.0}).animate(fps=10)
    misplaced = [abs((p.upper[2][1] + p.upper[3][1]) / 2 - 4.0 - rounded.top_dy[sharp.sample_indices[k]])
                 for k in swung for p in [sharp.draw_frame(k)]]
    assert max(misplaced) > ENGINE_TOLERANCE
    plt.close("all")


def test_a_run_without_theta2_is_refused_rather_than_drawn_without_its_upper_block(release):
    motion_only = dataclasses.replace(release, theta2=np.full_like(release.theta2, np.nan))
    with pytest.raises(vssw.InputError, match="theta2 is NaN"):
        motion_only.animate()
