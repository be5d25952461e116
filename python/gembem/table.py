"""The one reader of gembem's CSV files: columns by name, as numpy arrays.

Every CSV that gembem writes (steps.csv, history.csv, state_grains.csv, contacts/, fields/,
host_*.csv, ...) has one header line of column names and one row per record. A column whose
values are all integers becomes int64, all numbers float64, anything else (a contact's `j`,
`left` or `p9`; a host group's name) an array of str. gembem writes a whole double without a
point (`%.17g`: a rotation of 0 is "0"), so a quantity whole in every row reads as int64 too:
arithmetic promotes it, but in-place float updates need ``.astype(float)`` first.
"""
import csv
import os

import numpy as np


class Table(dict):
    """Columns of one CSV file, by name: ``t["pn"]`` is a numpy array with one value per row.

    A dict (column name -> array), so ``list(t)`` are the names in file order; ``t.nrows`` the
    rows, ``t.path`` where it came from, ``t.select(mask)`` a subset of rows, ``t.records()`` a
    numpy structured array for row-wise use.
    """

    def __init__(self, columns, path=None):
        super().__init__(columns)
        self.path = path
        lengths = {len(v) for v in self.values()}
        if len(lengths) > 1:
            raise ValueError(f"{path}: columns of different lengths {sorted(lengths)}")
        self.nrows = lengths.pop() if lengths else 0

    def __missing__(self, name):
        raise KeyError(f"{self.path or 'table'}: no column '{name}'; its columns are {', '.join(self)}")

    def select(self, rows):
        """The rows picked by a boolean mask or an index array, as a new Table."""
        return Table({k: v[rows] for k, v in self.items()}, self.path)

    def records(self):
        """The rows as a numpy structured array (fields in file order)."""
        out = np.empty(self.nrows, dtype=[(k, v.dtype) for k, v in self.items()])
        for k, v in self.items():
            out[k] = v
        return out

    def __repr__(self):
        return f"Table({self.path!r}, {self.nrows} rows, columns: {', '.join(self)})"


def _column(values):
    """The narrowest of int64, float64 and str that holds every value of a column."""
    try:
        return np.array([int(v) for v in values], dtype=np.int64)
    except ValueError:
        pass
    try:
        return np.array([float(v) for v in values], dtype=np.float64)
    except ValueError:
        return np.array(values, dtype=str)


def read_csv(path):
    """Reads a CSV file of gembem into a Table (see parse_csv)."""
    path = os.fspath(path)
    with open(path, newline="") as f:
        return parse_csv(f.read(), path)


def parse_csv(text, path="<text>"):
    """A Table of CSV text in gembem's form, e.g. what a gembem tool printed (path: its name in errors).

    Lines starting with '#' are comments. A row with another number of fields than the header
    (half a row left by a run that was killed) is an error naming the file and line: a resumed
    run cuts such rows back, a reader should not guess.
    """
    lines = [(n, line) for n, line in enumerate(text.splitlines(), 1) if line.strip() and not line.startswith("#")]
    if not lines:
        raise ValueError(f"{path}: empty file, expected a header line of column names")
    header = next(csv.reader([lines[0][1]]))
    rows = []
    for (n, _), row in zip(lines[1:], csv.reader(line for _, line in lines[1:])):
        if len(row) != len(header):
            raise ValueError(f"{path}:{n}: {len(row)} fields, expected {len(header)} as in the header "
                             f"({','.join(header)})")
        rows.append(row)
    if not rows:
        return Table({name: np.empty(0) for name in header}, path)
    return Table({name: _column([r[k] for r in rows]) for k, name in enumerate(header)}, path)
