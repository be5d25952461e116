"""Exceptions for a gembem command that failed, one class per exit status of `gembem run`.

A study can catch what it expects (a step that did not converge) and let the rest stop it.
"""
import signal


class GembemError(Exception):
    """`gembem` exited with a non-zero status: ``returncode``, its ``message`` (what it wrote on
    stderr, progress lines left out) and the ``command`` run."""

    def __init__(self, returncode, message, command):
        self.returncode, self.message, self.command = returncode, message.strip(), list(command)
        super().__init__(f"{' '.join(self.command)}: exit status {returncode}: {self.message or '(no message)'}")


class SceneError(GembemError):
    """Exit status 2: bad input (a scene, a state, a resume refused), found before any computation."""


class ConvergenceError(GembemError):
    """Exit status 3: a load step did not converge even cut back; the completed steps are kept."""


class OutputError(GembemError):
    """Exit status 4: an output could not be written (a full disk); the last checkpoint is whole."""


_BY_STATUS = {2: SceneError, 3: ConvergenceError, 4: OutputError}


def error_for(returncode, message, command):
    """The exception for an exit status (GembemError for any status without a class of its own;
    a negative status, as subprocess gives it, is the signal that killed gembem)."""
    if returncode < 0 and not message.strip():
        try:
            message = f"killed by {signal.Signals(-returncode).name} (gembem.resume continues the run)"
        except ValueError:
            message = f"killed by signal {-returncode}"
    return _BY_STATUS.get(returncode, GembemError)(returncode, message, command)
