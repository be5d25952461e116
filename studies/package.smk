# Included first by the repository's Snakefiles (studies/, validation/*/): this checkout's Python
# package (python/gembem), for the Snakefile and for the scripts its rules run, so that a
# workflow runs without PYTHONPATH from wherever its docs say. Its gembem command is then found
# as gembem.find_gembem says: $GEMBEM, this checkout's build/gembem, else gembem on PATH.
import os
import sys

_python = os.path.normpath(os.path.join(workflow.current_basedir, "..", "python"))
if _python not in sys.path:
    sys.path.insert(0, _python)
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (_python, os.environ.get("PYTHONPATH")) if p)
