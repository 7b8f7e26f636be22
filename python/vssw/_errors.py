"""The package's exceptions, raised alike for the program's errors (vssw.cli) and the library's (the typed API)."""


class Error(Exception):
    """A failed vssw call: `code` (the program's exit code for this kind of error), `stderr` (the program's error
    output; "" for the typed API), `result` (the command's JSON when it printed one, e.g. `compare` with a metric that
    could not be measured, or `check` with a bound out; else None)."""

    def __init__(self, message, code, stderr="", result=None):
        super().__init__(message)
        self.code = code
        self.stderr = stderr
        self.result = result


class InputError(Error, ValueError):
    """Bad input (exit code 2): a value out of range, NaN, an unknown option or setting, an unreadable record or study
    file. The message names the value."""


class SimulationError(Error, RuntimeError):
    """A simulation failed (exit code 3): the integrator gave up, the energy balance passed its ceiling, an engine's
    run blew up, slid or passed its CPU budget, a metric could not be measured (vssw.cli.compare: `result` holds the
    JSON with its `failures`), a failed row under strict."""


class BoundsError(Error):
    """A metric out of its bounds (exit code 1, `vssw check`): `result` holds the verdicts."""
