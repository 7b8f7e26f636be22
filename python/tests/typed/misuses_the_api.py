"""A script with type errors against vssw's annotations (test_types.py: mypy must refuse each marked line)."""
import vssw

run = vssw.simulate("analytic", height="4", thickness=0.4, hinge=0.7)  # error: a str for a number
name: int = run.engine  # error: the engine's name is a str
samples: str = run.t  # error: the times are an array
vssw.compare("ode", height=4.0, thickness=0.4, hinge=0.7).restitution.nonsense  # error: no such attribute
