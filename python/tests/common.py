"""What the Python package's tests share: a fresh directory per test, removed when it passes."""
import shutil
import tempfile
import unittest


class RunDirTest(unittest.TestCase):
    """A test case with ``self.tmp``, a directory of its own (kept when the test fails, to look at)."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix=f"gembem_{type(self).__name__}_")

    def tearDown(self):
        outcome = getattr(self, "_outcome", None)
        errors = getattr(getattr(outcome, "result", None), "errors", []) + \
            getattr(getattr(outcome, "result", None), "failures", [])
        if any(test is self for test, _ in errors):
            print(f"kept {self.tmp}")
        else:
            shutil.rmtree(self.tmp, ignore_errors=True)
