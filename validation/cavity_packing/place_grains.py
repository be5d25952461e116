#!/usr/bin/python3
"""The initial placement of the 27-grain cavity packing (validation C), written once into
scene.yaml: 4 grains of diameter 1.0 cm and 23 of 0.6 cm placed one by one at seeded random points
of the cavity's usable disc (radius 2.5 cm less the boundary particles' bulge), the large ones
first, overlapping their neighbours by at most 0.06 cm (a fifth of the small radius: random
placement without any overlap jams near 55 % coverage, these grains cover about 66 %); then one
small grain on the right (G) is pushed onto its nearest neighbour (H) to make the large overlap of
the paper's example. Deterministic: run it to see how the list was made.
"""
import math
import random

R_CAVITY, N_ELEMENTS = 2.5, 24
bulge = R_CAVITY * math.sin(math.pi / N_ELEMENTS)  # half an element's length: a particle's radius
usable = R_CAVITY * math.cos(math.pi / N_ELEMENTS) - bulge
rng = random.Random(5)
radii = [0.5] * 4 + [0.3] * 23
SLACK = 0.06
grains = []
for r in radii:
    for _ in range(100000):
        a, d = rng.uniform(0, 2 * math.pi), (usable - r) * math.sqrt(rng.random())
        x, y = d * math.cos(a), d * math.sin(a)
        if all(math.hypot(x - gx, y - gy) > r + gr - SLACK for gx, gy, gr in grains):
            grains.append((x, y, r))
            break
    else:
        raise SystemExit(f"could not place grain {len(grains)}")
# G: the small grain furthest to the right; H: its nearest neighbour. Push G towards H until
# they overlap by 40 % of the small radius.
g = max((k for k, q in enumerate(grains) if q[2] == 0.3), key=lambda k: grains[k][0])
h = min((k for k in range(len(grains)) if k != g),
        key=lambda k: math.hypot(grains[k][0] - grains[g][0], grains[k][1] - grains[g][1]))
(xg, yg, rg), (xh, yh, rh) = grains[g], grains[h]
dist = math.hypot(xh - xg, yh - yg)
target = rg + rh - 0.4 * 0.3
grains[g] = (xh + (xg - xh) * target / dist, yh + (yg - yh) * target / dist, rg)
print(f"# usable radius {usable:.4f} cm; G = grain {g}, H = grain {h}, overlap {rg + rh - target:.3f} cm")
for x, y, r in grains:
    print(f"    - [{x:.4f}, {y:.4f}, {r}]")
