#!/usr/bin/python3
"""The band measures of band_statistics.py on a biaxial box run of biaxial_control.py: per window
of the strain path and over the whole travel, the band measure, its shuffled null, the thickness,
the angle and the rotation ratio, with the walls' stress ratio q/p.

The measures are band_statistics.py's (figures.strip_share, band_statistics.strip_measures: the
0.5 cm strip, the refined direction, the shuffled null, the FWHM thickness, the rotations); only
the measuring window and the stress differ from the cavity's:

  window    the box's interior at the window's end (steps.csv width and height; the box stays
            centred on the origin: the walls move symmetrically) less MARGIN_D mean diameters from
            each wall (the walls order the grains next to them): the triangles whose centroid lies
            inside, and for the rotations the grains whose centre does;
  windows   the shear stage (gembem's shear_mean_stress) cut where its vertical strain e1 has grown
            by EVERY since the window's start, and the whole travel;
  q/p       the walls' stress ratio (s1 - s2) / (s1 + s2) at the window's end (steps.csv; the
            smooth walls are principal planes), the mobilised friction sin phi = q/p;
  angle     the band's direction from the horizontal (the minor principal stress: s2 < s1), 0-90
            deg, against theta_MC = 45 + phi/2 and theta_R = 45 + psi/2, sin psi = -(de1 + de2) /
            (de1 - de2) of the walls' strain over the window (compression +, psi > 0 dilation).

With them, per window, band_statistics.network_measures: the profile contrast across strips 1 d
wide (the largest over the directions, and the next family's), over its block null (bold where
it reaches band_statistics.BAND_BLOCK: a band or a band network) and its shuffled null, and the
share of the strain in the best strip 8 d wide over its shuffled null.

Usage: validation/localisation/box_bands.py DIR [OUT]  (DIR of biaxial_control.py: DIR/run, DIR/grains.csv)
       validation/localisation/box_bands.py --summary DIR ...   (runs measured: a row each, their mean)
Writes OUT/bands.md (the table), OUT/bands.csv and OUT/bands.png (OUT: DIR unless given; the stress ratio and band
measures along the path; the strain with the strip of the window whose band measure is the most
above its null, of the last window and of the whole travel)."""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import gembem  # noqa: E402
import band_statistics as bs  # noqa: E402  (the measures: written once, there and in figures.py)
import figures as fg  # noqa: E402

MARGIN_D = 3        # mean diameters of the box's interior left out along each wall
EVERY = 0.01        # vertical strain per window
SHEAR_STAGE = 3     # biaxial_control.py's stages: relax, isotropic, shear_mean_stress
OUTLINES = 3000     # the maps draw the grains' outlines up to this many grains (beyond, they hide the strain)


class BoxRun:
    """A box run in the form figures.accumulated_strain and band_statistics.strip_measures read."""

    def __init__(self, d):
        self.dir = d
        self.run = os.path.join(d, "run")
        self.r = gembem.Run(self.run)
        self.radii = fg.read_csv(os.path.join(d, "grains.csv"))["r"]
        self.d = 2 * self.radii.mean()
        self.s = fg.read_csv(os.path.join(self.run, "steps.csv"))
        shear = np.nonzero(self.s["stage"] == SHEAR_STAGE)[0]
        self.first, self.last = int(shear[0]), int(shear[-1])

    def half(self, k):
        """The measuring window's half width and half height at the end of step k."""
        m = MARGIN_D * self.d
        return 0.5 * self.s["width"][k] - m, 0.5 * self.s["height"][k] - m

    def windows(self):
        return strain_windows(self.s["e1"], self.first, self.last)


def strain_windows(e1, first, last, every=EVERY):
    """(k0, k1): consecutive runs of the steps first-last, each ending where the strain e1 (per
    step, at its end) has grown by `every` since the run's start (a last, shorter rest left out)."""
    out, k0 = [], first
    for k in range(first, last + 1):
        if e1[k] - e1[k0 - 1] >= every * (1 - 1e-9):
            out.append((k0, k))
            k0 = k + 1
    return out


def window_measures(br, k0, k1):
    """The band measures of the window of steps k0-k1 (a dict), and what draws it."""
    tri, g, ok, area, b = fg.accumulated_strain(br, k0, k1)
    hw, hh = br.half(k1)
    t = tri.triangles
    cx, cy = tri.x[t].mean(1), tri.y[t].mean(1)
    ok = ok & (np.abs(cx) <= hw) & (np.abs(cy) <= hh)
    among = (np.abs(b["x"]) <= hw) & (np.abs(b["y"]) <= hh)
    share, ashare, ang, axis = fg.strip_share(tri, g, ok, area, offset=True, dang=bs.DANG)
    out = {"k0": k0, "k1": k1, "e1": br.s["e1"][k1], "band": share, "band_area": ashare, "strip_ang": ang}
    out.update(bs.strip_measures(br, k0, k1, tri, g, ok, area, ang, axis, radius=math.hypot(hw, hh), among=among))
    out.update(bs.network_measures(tri, g, ok, area, br.d))
    del out["width"]
    s = br.s
    out["q_p"] = s["stress_ratio"][k1]
    de1, de2 = s["e1"][k1] - s["e1"][k0 - 1], s["e2"][k1] - s["e2"][k0 - 1]
    out["theta"] = min(out["ang"], 180 - out["ang"])
    out["theta_mc"] = 45 + math.degrees(math.asin(out["q_p"])) / 2
    out["theta_r"] = 45 + math.degrees(math.asin(np.clip(-(de1 + de2) / (de1 - de2), -1, 1))) / 2
    out["_draw"] = (tri, g, ok, None, None, None, br.r.grains(k1), out["ang"], out["axis"])
    return out


COLUMNS = [("steps", "steps"), ("e1", "e1 at end [%]"), ("q_p", "q/p at end"), ("band", "band measure"),
           ("band_null", "shuffled null"), ("ratio", "band / null"), ("band_area", "strip's area share"),
           ("thickness_d", "thickness [d]"), ("ang", "direction [deg from +x]"), ("theta", "to horizontal [deg]"),
           ("theta_mc", "theta_MC"), ("theta_r", "theta_R"), ("rot_ratio_med", "rotation ratio (medians)"),
           ("rot_ratio_med_null", "its null"), ("contrast", "profile contrast"),
           ("contrast_block", "its block null"), ("contrast_null", "its shuffled null"),
           ("contrast_ratio", "contrast / block null"), ("contrast_dirs", "contrast's directions [deg from +x]"),
           ("share_d", f"{fg.BAND_D:g} d strip share"), ("share_d_ratio", "/ its null")]


def cell(m, key):
    if key == "steps":
        return f"{m['k0']}-{m['k1']}"
    if key == "ratio":
        return f"{m['band'] / m['band_null']:.2f}"
    if key in ("contrast_ratio", "share_d_ratio"):
        v = m["contrast"] / m["contrast_block"] if key == "contrast_ratio" else m["share_d"] / m["share_d_null"]
        return f"**{v:.2f}**" if key == "contrast_ratio" and v >= bs.BAND_BLOCK else f"{v:.2f}"
    if key == "contrast_dirs":
        return f"{m['contrast_ang']:.0f}, {m['contrast_ang2']:.0f}"
    if key == "e1":
        return f"{100 * m['e1']:.2f}"
    return f"{m[key]:.1f}" if key in ("thickness_d", "ang", "theta", "theta_mc", "theta_r") else f"{m[key]:.3f}"


def table(br, rows, whole):
    s = br.s
    sh = slice(br.first, br.last + 1)
    kp = br.first + int(np.argmax(s["stress_ratio"][sh]))
    info = br.r.run_info
    head = (f"{len(br.radii)} grains, mean diameter d = {br.d:.4f} cm, box {s['width'][0]:.3f} cm = "
            f"{s['width'][0] / br.d:.1f} d wide at the start; windows of {100 * EVERY:g} % of vertical strain, "
            f"measured {MARGIN_D} d inside the walls; strip {fg.STRIP} cm = {fg.STRIP / br.d:.1f} d.\n"
            f"Run: {info.get('status')}, {br.last} steps, {float(np.sum(s['seconds'])):.0f} s of steps' wall time; "
            f"vertical strain at the end {100 * s['e1'][br.last]:.2f} %, volumetric {100 * s['ev'][br.last]:.2f} % "
            f"(compression +).\nPeak q/p {s['stress_ratio'][kp]:.3f} at step {kp} (e1 {100 * s['e1'][kp]:.2f} %); "
            f"q/p at the end {s['stress_ratio'][br.last]:.3f}.\n\n")
    nb = sum(m["contrast"] >= bs.BAND_BLOCK * m["contrast_block"] for m in rows)
    head += (f"Profile contrast >= {bs.BAND_BLOCK} x its block null in {nb} of {len(rows)} windows; the longest run of "
             f"them in one direction (to 15 deg, or its mirror image): {bs.persistent_band(rows)} windows (a band forms: 2 or more).\n\n")
    lines = ["| " + " | ".join(label for _, label in COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    for m in rows + [whole]:
        lines.append("| " + " | ".join(cell(m, k) for k, _ in COLUMNS) + " |")
    lines[-1] = lines[-1].replace("| ", "| whole travel ", 1)
    return head + "\n".join(lines) + "\n"


def figure(br, rows, whole, path):
    fig = plt.figure(figsize=(16, 10))
    grid = fig.add_gridspec(2, 6, height_ratios=[1, 1.3])
    axes = [fig.add_subplot(grid[0, 0:3]), fig.add_subplot(grid[0, 3:6])] + [fig.add_subplot(grid[1, 2 * i:2 * i + 2])
                                                                            for i in range(3)]
    s, sh = br.s, slice(br.first - 1, br.last + 1)
    ax = axes[0]
    ax.plot(100 * s["e1"][sh], s["stress_ratio"][sh], color="k", label="q/p (walls)")
    ax.plot(100 * s["e1"][sh], -s["ev"][sh] * 10, color="tab:green", label="dilation -ev x 10")
    ax.set_xlabel("vertical strain e1 [%]")
    ax.legend(fontsize=7)
    ax = axes[1]
    e = [100 * m["e1"] for m in rows]
    ax.plot(e, [m["band"] for m in rows], "o-", color="tab:blue", ms=3, label="band measure")
    ax.plot(e, [m["band_null"] for m in rows], "x--", color="tab:red", ms=4, label="shuffled null")
    ax.plot(e, [m["band_area"] for m in rows], ":", color="0.5", label="strip's area share")
    ax.axhline(whole["band"], color="tab:blue", lw=0.6, ls="-.", label="whole travel")
    ax.set_xlabel("vertical strain at the window's end [%]")
    ax.set_ylim(0, None)
    ax.legend(fontsize=7, loc="lower left")
    ax2 = ax.twinx()   # the profile contrast over its nulls
    ax2.plot(e, [m["contrast"] / m["contrast_block"] for m in rows], "s-", color="tab:purple", ms=3,
             label="profile contrast / block null")
    ax2.plot(e, [m["contrast"] / m["contrast_null"] for m in rows], "^:", color="tab:purple", ms=3,
             label="profile contrast / shuffled null")
    ax2.axhline(bs.BAND_BLOCK, color="tab:purple", lw=0.6, ls="--")
    ax2.set_ylim(0, None)
    ax2.set_ylabel("profile contrast / null (dashed: a band)", fontsize=8)
    ax2.legend(fontsize=7, loc="lower right")
    ext = 0.5 * max(s["width"][br.last], s["height"][br.last]) * 1.02
    top = max(rows, key=lambda m: m["band"] / m["band_null"])
    for ax, m, what in ((axes[2], top, f"largest band / null: steps {top['k0']}-{top['k1']}"),
                        (axes[3], rows[-1], f"last window, steps {rows[-1]['k0']}-{rows[-1]['k1']}"),
                        (axes[4], whole, f"whole travel, steps {whole['k0']}-{whole['k1']}")):
        tri, g, ok = m["_draw"][:3]
        tp, _ = bs.draw_band(ax, br, m, np.percentile(g[ok], 98), extent=ext, outlines=len(br.radii) <= OUTLINES)
        hw, hh = br.half(m["k1"])
        ax.plot([-hw, hw, hw, -hw, -hw], [-hh, -hh, hh, hh, -hh], color="tab:green", lw=0.6)
        ax.set_title(f"{what}: band {m['band']:.2f} (null {m['band_null']:.2f}) at {m['ang']:.0f} deg,\n"
                     f"thickness {m['thickness_d']:.1f} d, rotation ratio {m['rot_ratio_med']:.2f}", fontsize=8)
        fig.colorbar(tp, ax=ax, fraction=0.04, pad=0.01)
    fig.suptitle(f"Biaxial box, {len(br.radii)} grains ({os.path.basename(os.path.normpath(br.dir))}): the walls' "
                 f"stress ratio and dilation; the band measures per window;\nthe shear strain on the triangles of the "
                 f"centres, the band measure's {fg.STRIP} cm strip (dashed), the measuring window (green)", fontsize=9)
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    fig.savefig(path, dpi=110)
    plt.close(fig)
    fg.shrink_png(path)


def main(d, out):
    br = BoxRun(d)
    rows = [window_measures(br, k0, k1) for k0, k1 in br.windows()]
    whole = window_measures(br, br.first, br.last)
    text = table(br, rows, whole)
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "bands.md"), "w") as f:
        f.write(text)
    keys = ["k0", "k1", "e1", "q_p", "band", "band_null", "band_area", "thickness_d", "ang", "axis", "theta",
            "theta_mc", "theta_r", "rot_ratio", "rot_ratio_null", "rot_ratio_med", "rot_ratio_med_null", "spinning",
            "contrast", "contrast_null", "contrast_block", "contrast_ang", "contrast2", "contrast_ang2", "share_d",
            "share_d_null", "share_d_area", "share_d_ang"]
    with open(os.path.join(out, "bands.csv"), "w") as f:
        f.write("window," + ",".join(keys) + "\n")
        for name, m in [(str(i + 1), m) for i, m in enumerate(rows)] + [("whole", whole)]:
            f.write(name + "," + ",".join(f"{m[k]:.6g}" for k in keys) + "\n")
    figure(br, rows, whole, os.path.join(out, "bands.png"))
    print(text)


def summary(dirs):
    """One row per box run measured by main (DIR/bands.csv, DIR/run/steps.csv), then the mean and
    standard deviation of each run's numbers over the runs: the README's table of the boxes."""
    head = ("| run | steps' wall time [s] | peak q/p (e1 [%]) | windows >= " + f"{bs.BAND_BLOCK:g}" +
            " x block null | contrast / block null: range (median) | a band forms (windows in a row) | whole travel "
            "/ block null | next family / block null in the best window | best direction to the horizontal: median "
            "(range) [deg] | band / null (0.5 cm): median | thickness [d]: median | rotation ratio (null): median |")
    lines, runs = [head, "|" + "---|" * head.count(" | ") + "---|"], []
    for d in dirs:
        w = fg.read_csv(os.path.join(d, "bands.csv"))
        s = fg.read_csv(os.path.join(d, "run", "steps.csv"))
        win = w["window"] != "whole"
        windows = [{k: float(w[k][i]) for k in ("contrast", "contrast_block", "contrast_ang")} for i in np.nonzero(win)[0]]
        ratio = w["contrast"][win] / w["contrast_block"][win]
        to_h = np.minimum(w["contrast_ang"][win] % 180, 180 - w["contrast_ang"][win] % 180)
        kp = int(np.argmax(np.where(s["stage"] == SHEAR_STAGE, s["stress_ratio"], -np.inf)))
        r = {"seconds": float(np.sum(s["seconds"])), "peak": float(s["stress_ratio"][kp]),
             "band_windows": int(np.sum(ratio >= bs.BAND_BLOCK)), "ratio": float(np.median(ratio)),
             "in_a_row": bs.persistent_band(windows), "whole": float((w["contrast"] / w["contrast_block"])[~win][0]),
             # the next direction family in the best window, as band_statistics' net_ratio2 of the cavity
             "next": float((w["contrast2"][win] / w["contrast_block"][win])[int(np.argmax(ratio))]),
             "to_h": float(np.median(to_h)), "band": float(np.median(w["band"][win] / w["band_null"][win])),
             "thickness": float(np.median(w["thickness_d"][win])), "rot": float(np.median(w["rot_ratio_med"][win])),
             "rot_null": float(np.median(w["rot_ratio_med_null"][win]))}
        runs.append(r)
        lines.append(f"| {os.path.basename(os.path.normpath(d))} | {r['seconds']:.0f} | {r['peak']:.3f} "
                     f"({100 * s['e1'][kp]:.1f}) | {r['band_windows']} of {len(windows)} | {ratio.min():.2f}-"
                     f"{ratio.max():.2f} ({r['ratio']:.2f}) | {'yes' if r['in_a_row'] >= 2 else 'no'} ({r['in_a_row']}) | "
                     f"{r['whole']:.2f} | {r['next']:.2f} | {r['to_h']:.0f} ({to_h.min():.0f}-{to_h.max():.0f}) | "
                     f"{r['band']:.2f} | {r['thickness']:.1f} | {r['rot']:.2f} ({r['rot_null']:.2f}) |")

    def ms(key, fmt):
        v = np.array([r[key] for r in runs], float)
        return f"{v.mean():{fmt}} +- {v.std(ddof=1) if len(v) > 1 else 0:{fmt}}"
    formed = sum(r["in_a_row"] >= 2 for r in runs)
    lines.append(f"| mean +- sd of {len(runs)} | {ms('seconds', '.0f')} | {ms('peak', '.3f')} | {ms('band_windows', '.1f')} | "
                 f"({ms('ratio', '.2f')}) | {formed} of {len(runs)} ({ms('in_a_row', '.1f')}) | {ms('whole', '.2f')} | "
                 f"{ms('next', '.2f')} | {ms('to_h', '.0f')} | {ms('band', '.2f')} | {ms('thickness', '.1f')} | "
                 f"{ms('rot', '.2f')} ({np.mean([r['rot_null'] for r in runs]):.2f}) |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "--summary":
        print(summary(sys.argv[2:]), end="")
    elif len(sys.argv) not in (2, 3):
        raise SystemExit(__doc__)
    else:
        main(sys.argv[1], sys.argv[-1])
