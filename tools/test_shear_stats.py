#!/usr/bin/python3
"""tools/shear_stats.py on hand-made runs whose q/p0 and p/p0 are linear in e1 (so that the
interpolation is exact and every path mean is the line's value at the mean grid strain, 2.625 %):
gembem's work counts, path means, the offsets against LAMMPS's slowest run, LAMMPS's spread between
rates and between repeats, the CPU ratios, a run stopped short, a malformed list."""
import os
import subprocess
import sys
import tempfile

STATS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "shear_stats.py")
HEAD = "n\tcode\tlabel\tstatus\tsteps\tseed\tcurve\tcpu\twall\tmb\tforce\n"
failures = passed = 0


def check(name, condition, text=""):
    global failures, passed
    print(("ok   " if condition else "FAIL ") + name)
    if not condition:
        print(text)
    failures += 0 if condition else 1
    passed += 1 if condition else 0


def stresses(p0, kq, kp, e1):
    """s1, s2 with q = p0 kq e1 and p = p0 (1 + kp e1)."""
    q, p = p0 * kq * e1, p0 * (1 + kp * e1)
    return p + q, p - q


with tempfile.TemporaryDirectory() as tmp:
    # gembem: 25 load steps of 0.2 % (off the 0.25 % grid), q/p0 = 9 e1, p/p0 = 1 + 20 e1, p0 = 100
    its = [2] * 25
    its[3], its[7] = 5, 3  # iterations: mean 54/25 = 2.16, median 2, max 5
    with open(os.path.join(tmp, "steps.csv"), "w") as f:
        f.write("step,e1,s1,s2,iterations,sweeps,factorisations,substeps\n")
        for k in range(26):
            s1, s2 = stresses(100.0, 9.0, 20.0, 0.002 * k)
            f.write(f"{k},{0.002 * k!r},{s1!r},{s2!r},{its[k - 1] if k else 0},{100 if k else 0},1,{2 if k == 4 else int(k > 0)}\n")
    # LAMMPS: 1000 steps q/p0 = 11 e1 (seed 1); 2000 steps q/p0 = 10 e1 (seed 1, the slowest);
    # 1000 steps seed 2: 11 e1 plus 0.05 at e1 = 3 %; all p/p0 = 1 + 20 e1, p0 = 200
    def curve(name, kq, bump=0.0, last=20):
        with open(os.path.join(tmp, name), "w") as f:
            f.write("step e1 e2 s1 s2\n")
            for k in range(last + 1):
                e = 0.0025 * k
                s1, s2 = stresses(200.0, kq, 20.0, e)
                if k == 12:
                    s1, s2 = s1 + 200.0 * bump, s2 - 200.0 * bump  # q/p0 + bump
                f.write(f"{50 * k} {e!r} {-e!r} {s1!r} {s2!r}\n")
    curve("l1000.txt", 11.0)
    curve("l2000.txt", 10.0)
    curve("l1000s2.txt", 11.0, bump=0.05)
    curve("short.txt", 10.0, last=12)
    runs = os.path.join(tmp, "runs.tsv")
    with open(runs, "w") as f:
        f.write(HEAD)
        f.write(f"1000\tgembem\tgembem 25\tconverged\t25\t\t{tmp}/steps.csv\t2.00\t2.5\t80\t90\n")
        f.write(f"1000\tlammps\tL 1000\tsheared\t1000\t1\t{tmp}/l1000.txt\t10.00\t11\t30\t-\n")
        f.write(f"1000\tlammps\tL 2000\tsheared\t2000\t1\t{tmp}/l2000.txt\t20.00\t21\t30\t-\n")
        f.write(f"1000\tlammps\tL 1000 s2\tsheared\t1000\t2\t{tmp}/l1000s2.txt\t10.00\t11\t30\t-\n")
        f.write(f"1000\tlammps\tL short\tfailed\t4000\t3\t{tmp}/short.txt\t5.00\t6\t30\t-\n")
    curves = os.path.join(tmp, "curves.csv")
    out = subprocess.run([sys.executable, STATS, runs, "--curves", curves], capture_output=True, text=True)
    text = out.stdout
    rows = {line[:-2].split(" | ")[1]: line[:-2].split(" | ") for line in text.splitlines() if line.startswith("| 1000 |")}
    check("exit 0", out.returncode == 0, out.stderr)
    check("LAMMPS's slowest is the seed-1 run of most steps", "LAMMPS's slowest: L 2000" in text, text)
    g = rows.get("gembem 25", [""] * 15)
    check("gembem's work: Newton mean / median / max 2.2 / 2 / 5", "Newton 2.2 / 2 / 5;" in g[3], g[3])
    check("gembem's work: smoother steps a step 100 each", "smoother steps 100.0 / 100 / 100" in g[3], g[3])
    check("gembem's work: the one step cut back", g[3].endswith("; 1 load step cut back"), g[3])
    check("gembem's p0 100 and path means 9 x 0.02625, 1 + 20 x 0.02625",
          g[8] == "100" and g[9] == "0.2363" and g[10] == "1.5250", str(g))
    check("gembem at the end: 0.45, 2", g[11] == "0.4500, 2.0000", g[11])
    check("gembem off the slowest: q -10 %, p 0 %", g[12] == "-10.0 %, +0.0 %", g[12])
    check("CPU ratios 10/2 and 20/2", g[13] == "1000: 5.00; 2000: 10.00", g[13])
    s = rows.get("L short", [""] * 15)
    check("a run short of 5 % has no path mean", s[9] == "-" and s[10] == "-", str(s))
    check("the slowest has no offset against itself", rows.get("L 2000", [""] * 15)[12] == "-")
    check("LAMMPS's spread in q: 10 % of the slowest's",
          "path mean q/p0: 0.2625 to 0.2888, 10.0 % of the slowest's" in text, text)
    check("LAMMPS at 1000 against 2000: q +10 %, p 0 %",
          "LAMMPS at 1000 time steps against 2000 (half its rate): path means q +10.0 %, p +0.0 %" in text, text)
    # the repeat: mean q 0.28875 + 0.05 / 20; +0.9 %; 0.05 at 3 % is 17 % of 0.28875
    check("the repeat: path means and the largest difference in q",
          "seed 2 against seed 1: path means q +0.9 %, p +0.0 %; q/p0 differs by up to 0.0500 (17 % of the path "
          "mean of q) at e1 = 3 %" in text, text)
    with open(curves) as f:
        lines = f.read().splitlines()
    check("curves: the grid's 21 points and a q and p column per complete run",
          len(lines) == 22 and lines[0].count(",") == 8 and lines[13].startswith("0.03,"), "\n".join(lines[:3]))
    with open(runs, "w") as f:
        f.write("n\tcode\n")
    out = subprocess.run([sys.executable, STATS, runs], capture_output=True, text=True)
    check("a list without the header is refused", out.returncode != 0 and "expected the header" in out.stderr,
          out.stderr)

print(f"{passed} passed, {failures} failed")
sys.exit(1 if failures else 0)
