"""Running the `gembem` command from Python: its progress as it goes, its failures as exceptions.

gembem writes its progress line (step k of n, the stress ratio unless the scene has a host,
iterations, elapsed) only when its stderr is a terminal, so the command runs with stderr on a
pseudo-terminal (pty, standard library) and its lines are parsed into Progress records;
everything else it writes on stderr is kept as the message of the exception raised when it fails
(gembem.errors).
"""
import os
import pty
import re
import selectors
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass

from .errors import error_for
from .rundir import Run
from .scene import Scene

_HERE = os.path.dirname(os.path.abspath(__file__))
# The build tree of the checkout this package lives in (python/gembem -> build/gembem).
_BUILD_TREE = os.path.normpath(os.path.join(_HERE, "..", "..", "build", "gembem"))
try:  # written by cmake --install: the installed command beside this installed package
    from ._paths import BINDIR as _BINDIR
    _INSTALLED = os.path.join(_BINDIR, "gembem")
except ImportError:  # this package in a checkout
    _INSTALLED = None
# A hybrid scene's line has no stress ratio (a host has no box stresses).
_PROGRESS = re.compile(r"step (\d+) of (\d+)(?:\s+stress ratio (\S+))?\s+iterations (\d+)\s+elapsed (\S+) s")


@dataclass(frozen=True)
class Progress:
    """One of gembem's progress lines: after load step ``step`` of ``total`` (step 0: the initial
    state); stress_ratio NaN for a hybrid scene, whose host has no box stresses."""
    step: int
    total: int
    stress_ratio: float
    iterations: int
    elapsed: float
    line: str


def find_gembem(gembem=None):
    """The gembem executable: the argument, else $GEMBEM, else the one installed with this package
    (cmake --install, the .deb), else the build tree of this checkout (build/gembem), else
    `gembem` on PATH. An argument or $GEMBEM that is not an executable is an error, not a reason
    to look elsewhere."""
    for given, what in ((gembem, "the gembem argument"), (os.environ.get("GEMBEM"), "$GEMBEM")):
        if given:
            path = shutil.which(os.fspath(given))
            if not path:
                raise FileNotFoundError(f"{what} is '{given}': not an executable file")
            return path
    for candidate in _INSTALLED, _BUILD_TREE:
        if candidate and os.access(candidate, os.X_OK):
            return candidate
    path = shutil.which("gembem")
    if not path:
        raise FileNotFoundError("no gembem executable: expected the gembem argument, $GEMBEM, "
                                f"{_INSTALLED or _BUILD_TREE} or gembem on PATH")
    return path


def print_progress(p):
    """The default progress display: gembem's own line, rewritten in place on stderr."""
    sys.stderr.write("\r" + p.line)
    if p.step == p.total:
        sys.stderr.write("\n")
    sys.stderr.flush()


def run(scene, run_dir, *, overwrite=False, gembem=None, progress=print_progress, quiet=False,
        timeout=None, env=None, grains_file=None):
    """Runs a scene into run_dir (`gembem run SCENE -o RUN_DIR`) and returns its gembem.rundir.Run.

    scene: a Scene (written to RUN_DIR.yaml beside the run directory, which gembem needs again to
    resume it; grains_file as for Scene.write, relative to run_dir's parent: give each run its own
    name if their grains differ), or the path of a scene file. progress: called
    with each Progress (None: no display). quiet: neither progress nor gembem's summary line.
    timeout: seconds, after which gembem is killed and TimeoutError raised (the run can be
    resumed). env: environment variables added for gembem (e.g. OPENBLAS_NUM_THREADS).
    Raises SceneError (exit 2), ConvergenceError (3), OutputError (4), GembemError (other).
    """
    run_dir = os.fspath(run_dir)
    if isinstance(scene, Scene):
        path = run_dir.rstrip(os.sep) + ".yaml"
        if (not overwrite and os.path.isdir(run_dir) and os.path.exists(path)
                and _text(path) != scene.to_yaml(grains_file)):
            raise FileExistsError(f"{path}: the scene of an earlier run (a resume needs it), not this scene; "
                                  "expected overwrite=True to replace that run, or another run_dir")
        scene = scene.write(path, grains_file=grains_file)
    args = ["run", os.fspath(scene), "-o", run_dir] + (["--overwrite"] if overwrite else [])
    execute(args, gembem=gembem, progress=progress, quiet=quiet, timeout=timeout, env=env)
    return Run(run_dir)


def _text(path):
    with open(path) as f:
        return f.read()


def resume(run_dir, scene=None, *, gembem=None, progress=print_progress, quiet=False, timeout=None, env=None):
    """Continues an interrupted run from its checkpoint (`gembem run --resume RUN_DIR [SCENE]`)."""
    args = ["run", "--resume", os.fspath(run_dir)] + ([os.fspath(scene)] if scene is not None else [])
    execute(args, gembem=gembem, progress=progress, quiet=quiet, timeout=timeout, env=env)
    return Run(run_dir)


def execute(args, *, gembem=None, progress=print_progress, quiet=False, timeout=None, env=None):
    """Runs `gembem ARGS...`, progress to the callback, other output echoed unless quiet; returns
    gembem's stdout; raises the gembem.errors exception of a non-zero exit status."""
    command = [find_gembem(gembem)] + [os.fspath(a) for a in args] + (["--quiet"] if quiet else [])
    master, slave = pty.openpty()
    try:
        proc = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=slave,
                                env=dict(os.environ, **(env or {})))
    finally:
        os.close(slave)
    stream = _Streams(progress, quiet)
    try:
        stream.pump(proc, master, timeout)
        proc.wait()
    finally:
        os.close(master)
        proc.stdout.close()
        if proc.poll() is None:   # interrupted (KeyboardInterrupt, timeout): gembem must not run on
            proc.kill()
            proc.wait()
    if proc.returncode != 0:
        raise error_for(proc.returncode, "\n".join(stream.messages), command)
    return "".join(stream.stdout)


class _Streams:
    """Splits gembem's stderr (on the pty: '\\r' before each progress line, '\\r\\n' line ends)
    into progress records and message lines, and gathers its stdout."""

    def __init__(self, progress, quiet):
        self.progress, self.quiet = progress, quiet
        self.messages, self.stdout = [], []
        self.last_step = None
        self.mid_line = False   # print_progress left its line open on stderr
        self.pending = ""

    def pump(self, proc, master, timeout):
        deadline = None if timeout is None else time.monotonic() + timeout
        sel = selectors.DefaultSelector()
        sel.register(master, selectors.EVENT_READ, "err")
        sel.register(proc.stdout, selectors.EVENT_READ, "out")
        open_streams = 2
        while open_streams:
            wait = None if deadline is None else max(0.0, deadline - time.monotonic())
            events = sel.select(wait)
            if not events and deadline is not None and time.monotonic() >= deadline:
                raise TimeoutError(f"gembem killed after {timeout} s (resume it with gembem.resume)")
            for key, _ in events:
                try:
                    data = os.read(key.fd, 65536)
                except OSError:   # EIO: the pty's other side is closed, gembem has ended
                    data = b""
                if not data:
                    sel.unregister(key.fileobj)
                    open_streams -= 1
                elif key.data == "out":
                    text = data.decode(errors="replace")
                    self.stdout.append(text)
                    if not self.quiet:
                        sys.stdout.write(text)
                        sys.stdout.flush()
                else:
                    self.stderr(data.decode(errors="replace"))
        self.stderr("\n")
        sel.close()

    def stderr(self, text):
        parts = re.split(r"[\r\n]", self.pending + text)
        self.pending = parts.pop()
        for line in parts:
            self.line(line)
        self.line(self.pending, partial=True)   # a progress line is complete before its '\r'

    def line(self, line, partial=False):
        m = _PROGRESS.search(line)
        if m:
            step = int(m.group(1))
            if step != self.last_step and self.progress is not None and not self.quiet:
                ratio = float(m.group(3)) if m.group(3) is not None else float("nan")
                p = Progress(step, int(m.group(2)), ratio, int(m.group(4)), float(m.group(5)), line.strip())
                self.progress(p)
                self.mid_line = self.progress is print_progress and p.step < p.total
            self.last_step = step
        elif line.strip() and not partial:
            self.messages.append(line.rstrip())
            if not self.quiet:
                sys.stderr.write(("\n" if self.mid_line else "") + line.rstrip() + "\n")
                self.mid_line = False
