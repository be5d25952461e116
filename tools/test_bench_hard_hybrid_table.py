#!/usr/bin/python3
"""tools/bench_hard_hybrid_table.py on hand-made run directories: the medians, ratios and marks
of a finished run, and a run stopped in a step whose history.csv cycles (numbers counted by hand)."""
import os
import subprocess
import sys
import tempfile

TABLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bench_hard_hybrid_table.py")
STEPS_HEAD = "step,stage,iterations,max_fixing_force,seconds,substeps,trials,factorisations,sweeps,accuracy\n"
HISTORY_HEAD = "step,attempt,iteration,max_fixing_force,wall_residual,largest_move,damping,length\n"
failures = 0


def check(name, condition):
    global failures
    print(("ok   " if condition else "FAIL ") + name)
    failures += 0 if condition else 1


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def table(run_dir, code):
    return subprocess.run([sys.executable, TABLE, run_dir, "--exit", code], capture_output=True, text=True, check=True).stdout


with tempfile.TemporaryDirectory() as tmp:
    # A finished run: steps 1-5 with sweeps 100, 300, 200, 5000, 400 (median 300) and iterations
    # 2, 2, 3, 40, 2 (median 2); step 4 is 16.7 and 20 times the median: marked.
    done = os.path.join(tmp, "done")
    os.mkdir(done)
    rows = [(1, 2, 100), (2, 2, 300), (3, 3, 200), (4, 40, 5000), (5, 2, 400)]
    write(os.path.join(done, "steps.csv"), STEPS_HEAD + "0,0,0,0.01,0,0,0,0,0,0.05\n" + "".join(
        f"{s},1,{i},0.04,1.5,1,{i},1,{w},0.05\n" for s, i, w in rows))
    # Step 4's history: 40 rows falling 10, 9, ..., 1 then flat at 1 for 30 rows: a plateau (period 1).
    forces = [10 - k for k in range(10)] + [1.0] * 30
    write(os.path.join(done, "history.csv"), HISTORY_HEAD + "".join(
        f"4,1,{k + 1},{f},0,0,0,0\n" for k, f in enumerate(forces)))
    write(os.path.join(done, "run_info.yaml"), "status: completed\nmessage: \"\"\n")
    out = table(done, "0")
    lines = out.splitlines()
    check("status and exit", lines[0].startswith("done: status completed, exit 0"))
    check("medians", "median step: 2 iterations, 300 sweeps" in out)
    step4 = next(line for line in lines if line.split()[:1] == ["4"])
    check("step 4's ratios 16.7 and 20.0, marked", step4.split()[-4:] == ["16.7", "20.0", "<-", ">10x"])
    step2 = next(line for line in lines if line.split()[:1] == ["2"])
    check("step 2's ratios 1.0 and 1.0, unmarked", step2.split()[-2:] == ["1.0", "1.0"])
    check("fixing force over accuracy 0.8", step2.split()[8] == "0.800")
    check("costliest step 4", "costliest step 4:" in out)
    check("10 new lows, 30 rows without", "new lows 10; longest stretch without a new low 30 rows" in out)
    check("a plateau", "repeat with period 1" in out)

    # A run stopped in step 2 (exit 124): step 1 finished; step 2's 40 rows fall 8, 7, 6, 5 then
    # alternate 3, 4 for 36 rows (period 2); its last in-step checkpoint: 2 + 30 iterations, 7 sweeps.
    cut = os.path.join(tmp, "cut")
    os.mkdir(cut)
    write(os.path.join(cut, "steps.csv"), STEPS_HEAD + "0,0,0,0.01,0,0,0,0,0,0.05\n1,1,2,0.04,1.5,1,2,1,7,0.05\n")
    forces = [8, 7, 6, 5] + [3, 4] * 18
    write(os.path.join(cut, "history.csv"), HISTORY_HEAD + "1,1,1,3,0,0,0,0\n" + "".join(
        f"2,1,{k + 1},{f},0,0,0,0\n" for k, f in enumerate(forces)))
    write(os.path.join(cut, "run_info.yaml"), "status: running\n")
    write(os.path.join(cut, "checkpoint.txt"), "gembem_checkpoint 5\nstep 2 1 2 0 0 0 0 0\n"
          "progress 0 0 2 1 0 30 1\nwork 5 6 7000\nstall 0 inf 0\n")
    out = table(cut, "124")
    check("status running, exit 124", out.startswith("cut: status running, exit 124"))
    check("step 2 unfinished after 40 rows", "   2     -      40          ? (unfinished" in out)
    check("its checkpoint's work, 1000 times the median", "32 iterations, 5 trials, 6 factorisations, 7000 sweeps (1000.0 x" in out)
    check("costliest step 2", "costliest step 2:" in out)
    check("lowest 3 at row 5", "lowest 3 at row 5" in out)
    check("a cycle of period 2", "repeat with period 2" in out and "a cycle through 3, 4" in out)

print(f"{failures} failed")
sys.exit(1 if failures else 0)
