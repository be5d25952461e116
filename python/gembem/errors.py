"""Exceptions for a gembem command that failed, one class per exit status of `gembem run`.

A study can catch what it expects (a step that did not converge) and let the rest stop it.
"""
import re
import signal


# gembem's place of an error in a file: "file:line:column: what was expected"
_WHERE = re.compile(r"^(.+?):(\d+):(\d+): ")


class GembemError(Exception):
    """`gembem` exited with a non-zero status, or a call of its library (gembem.library) returned
    one (its gb_status, the same numbers): ``returncode``, its ``message`` (what it wrote on
    stderr, progress lines left out; the library's message) and the ``command`` run (the library
    function and its argument). Where the message starts with a place in a file, ``file``,
    ``line`` and ``column`` give it (else None)."""

    def __init__(self, returncode, message, command, what="exit status"):
        self.returncode, self.message, self.command = returncode, message.strip(), list(command)
        where = _WHERE.match(self.message)
        self.file, self.line, self.column = (where[1], int(where[2]), int(where[3])) if where else (None, None, None)
        super().__init__(f"{' '.join(self.command)}: {what} {returncode}: {self.message or '(no message)'}")


class SceneError(GembemError):
    """Exit status 2: bad input (a scene, a state, a resume refused), found before any computation."""


class ConvergenceError(GembemError):
    """Exit status 3: a load step did not converge even cut back; the completed steps are kept."""


class OutputError(GembemError):
    """Exit status 4: an output could not be written (a full disk); the last checkpoint is whole."""


_BY_STATUS = {2: SceneError, 3: ConvergenceError, 4: OutputError}


def error_for(returncode, message, command, what="exit status"):
    """The exception for an exit status (GembemError for any status without a class of its own;
    a negative status, as subprocess gives it, is the signal that killed gembem); what: how the
    status is named in the exception's text."""
    if returncode < 0 and not message.strip():
        try:
            message = f"killed by {signal.Signals(-returncode).name} (gembem.resume continues the run)"
        except ValueError:
            message = f"killed by signal {-returncode}"
    return _BY_STATUS.get(returncode, GembemError)(returncode, message, command, what)
