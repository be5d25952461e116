"""The standard figures of a run directory, and a scene edited by its keys, from the command line.

    PYTHONPATH=python /usr/bin/python3 -m gembem figures DIR [OUT_DIR]

Draws every figure the directory's files allow into OUT_DIR (default RUN_DIR/figures) and prints
each file with a line on what it shows. A run (`gembem run`): the force chains of the final state,
the stress ratio against the shear strain (box scenes), the convergence of its slowest load step,
the last contact rose and strain map, the localisation index of every step, and with a host its
cavity wall's hoop stress (first and last step), stress field and load-displacement curve. A
packing (`gembem pack`): its force chains, grain sizes and contact force distribution.

    PYTHONPATH=python /usr/bin/python3 -m gembem scene IN.yaml -o OUT.yaml [--set KEY=VALUE]
        [--add KEY=VALUE] [--delete KEY] ...

Writes IN's scene to OUT with the edits applied in the order given, through gembem.Scene (its file
names made absolute, so OUT may be written anywhere). KEY is dotted, list items by index
(`loading.0.relax.steps`); VALUE is YAML flow (`{kn: 1000, kt: 500}`, `[0, 0]`, `cholmod`).
--set replaces a value that IN has, --add creates one it has not (maps on the way created),
--delete removes one it has: a key that is not (or, for --add, is already) there is refused with
exit status 2 and its name, so that an edit cannot silently do nothing.
"""
import argparse
import os
import sys

import numpy as np

from . import figures
from .rundir import Packing, open_directory
from .scene import Scene
from .yamlfile import parse_yaml


def standard_figures(run, out):
    """Draws every standard figure the directory's files allow (a Run or a Packing); yields
    (path, what it shows)."""
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "force_chains.png")
    figures.force_chains(run, path=path)
    yield path, "grains of the final state, line width proportional to each contact's normal force"
    if isinstance(run, Packing):
        yield from _packing_figures(run, out)
    else:
        yield from _run_figures(run, out)


def _packing_figures(packing, out):
    path = os.path.join(out, "size_distribution.png")
    figures.size_distribution(packing, path=path)
    yield path, "the grains' radii as cumulative distributions, by number and by area"
    if packing.state.contacts.nrows:
        path = os.path.join(out, "force_distribution.png")
        figures.force_distribution(packing, path=path)
        yield path, "the normal contact forces over their mean, as a probability density (log scale)"


def _run_figures(run, out):
    has = lambda name: os.path.exists(os.path.join(run.path, name))  # noqa: E731
    s = run.steps
    if not has("host_steps.csv"):   # a hybrid run has no box: its stresses and strains are 0
        path = os.path.join(out, "stress_strain.png")
        figures.stress_strain(run, path=path)
        yield path, "stress ratio (s1 - s2)/(s1 + s2) against e1 - e2, every load step"
    if has("history.csv") and run.history.nrows:
        step = int(s["step"][np.argmax(s["iterations"])])
        if np.any(run.history["step"] == step):
            path = os.path.join(out, f"convergence_{step:06d}.png")
            figures.convergence(run, step, path=path)
            yield path, f"largest fixing force per iteration of load step {step}, the one with most iterations"
    roses = run.steps_of("contacts", "rose")
    if roses:
        path = os.path.join(out, f"rose_{roses[-1]:06d}.png")
        figures.rose(run, roses[-1], path=path)
        yield path, f"contact directions at step {roses[-1]}"
    maps = run.steps_of("fields", "triangles", "vtu")
    if maps:
        path = os.path.join(out, f"strain_map_{maps[-1]:06d}.png")
        figures.strain_map(run, maps[-1], path=path)
        yield path, f"shear strain increment of step {maps[-1]} on the grain centres' triangles"
    if has("localisation.csv"):
        loc = run.localisation
        if np.any((loc["step"] > 0) & np.isfinite(np.asarray(loc["localisation_index"], dtype=float))):
            path = os.path.join(out, "localisation_index.png")
            figures.localisation_index(run, path=path)
            yield path, "the localisation index of each load step's strain increment (0.1: uniform strain)"
    walls = run.steps_of("fields", "host_wall")
    if walls:
        steps = sorted({walls[0], walls[-1]})
        path = os.path.join(out, "cavity_wall.png")
        figures.cavity_wall(run, steps, path=path)
        yield path, (f"the host's hoop stress along the cavity wall at step{'s' if len(steps) > 1 else ''} "
                     f"{' and '.join(map(str, steps))}, with the grains and for the empty cavity")
    if has("host_field.vtu"):
        path = os.path.join(out, "host_stress.png")
        figures.host_stress(run, path=path)
        yield path, "the host's in-plane von Mises stress at the end, under the grains' force chains"
        pick = figures.loaded_group(run)
        if pick is None:
            return
        group, axis = pick
        path = os.path.join(out, f"load_displacement_{group}.png")
        figures.load_displacement(run, group, axis, path=path)
        yield path, f"force on the host's '{group}' against its displacement along {axis} (the loaded group)"


class SceneEditError(ValueError):
    """An edit the scene refuses: a key it has not (--set, --delete) or has already (--add)."""


def edit_scene(scene, edits):
    """scene with edits applied in order: (op, arg) with op "set", "add" (arg KEY=VALUE) or
    "delete" (arg KEY); SceneEditError naming the edit and its key when one cannot apply."""
    for op, arg in edits:
        key, eq, text = arg.partition("=")
        if op != "delete" and not eq:
            raise SceneEditError(f"--{op} {arg}: expected KEY=VALUE")
        if op == "add":
            if scene.has(key):
                raise SceneEditError(f"--add {key}: the scene has '{key}' already (--set replaces it)")
        else:
            try:
                scene.value(key)
            except KeyError as e:
                hint = " (--add creates it)" if op == "set" else ""
                raise SceneEditError(f"--{op} {key}: the scene has no '{e.args[0]}'{hint}") from None
        if op == "delete":
            scene = scene.without(key)
        else:
            try:
                value = parse_yaml(text)
            except Exception as e:  # yaml.YAMLError: the value's own message
                raise SceneEditError(f"--{op} {key}: the value is not YAML: {e}") from None
            try:
                scene = scene.with_value(key, value)
            except (AttributeError, IndexError, TypeError, ValueError):   # a missing list item, or a value no map
                raise SceneEditError(f"--{op} {key}: a key on the way is neither a map nor a list's item") from None
    return scene


class _Edit(argparse.Action):
    """--set/--add/--delete, kept in the order given."""

    def __call__(self, parser, namespace, values, option_string=None):
        getattr(namespace, self.dest).append((option_string.lstrip("-"), values))


def scene_command(a):
    """gembem scene: IN edited and written to OUT; the exit status (2: a refused edit or bad IN)."""
    try:
        scene = edit_scene(Scene.load(a.scene), a.edits)
        lines = " ".join(f"--{op} {arg}" for op, arg in a.edits)
        scene.write(a.output, comment=f"{os.path.abspath(a.scene)} edited by python3 -m gembem scene" +
                    (f":\n{lines}" if lines else ""))
    except SceneEditError as e:
        print(f"gembem scene: {a.scene}: {e}", file=sys.stderr)
        return 2
    except (OSError, ValueError) as e:
        print(f"gembem scene: {e}", file=sys.stderr)
        return 2
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python3 -m gembem", description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="command", required=True)
    f = sub.add_parser("figures", help="the standard figures of a run or packing directory")
    f.add_argument("run_dir")
    f.add_argument("out_dir", nargs="?")
    s = sub.add_parser("scene", help="a scene edited by its keys (--set, --add, --delete), written to -o OUT")
    s.add_argument("scene", help="the scene read (IN.yaml)")
    s.add_argument("-o", "--output", required=True, help="the scene written (OUT.yaml; may be IN)")
    s.set_defaults(edits=[])
    s.add_argument("--set", dest="edits", action=_Edit, metavar="KEY=VALUE", help="replace the value IN has at KEY")
    s.add_argument("--add", dest="edits", action=_Edit, metavar="KEY=VALUE", help="create KEY, which IN has not")
    s.add_argument("--delete", dest="edits", action=_Edit, metavar="KEY", help="remove KEY, which IN has")
    a = ap.parse_args(argv)
    if a.command == "scene":
        return scene_command(a)
    try:
        run = open_directory(a.run_dir)
        for path, what in standard_figures(run, a.out_dir or os.path.join(a.run_dir, "figures")):
            print(f"{path}: {what}")
    except (OSError, ValueError, KeyError) as e:
        print(f"gembem figures: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
