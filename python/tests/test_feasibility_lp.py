"""The feasibility factor of `capability --loads` against an independent solution: a linear
programme (scipy's HiGHS) over each unit's region as a polygon, one programme per combination of
an azimuth's allowed arcs and a rudder propeller's sign of thrust, the largest λ over them.

The regions are written here from their definition (docs/theory.md), not from the allocator:
an azimuth's disc as the 32-sided polygon inscribed in it, cut to a wedge of allowed directions
of at most 180°; a tunnel or propeller between its ratings; a rudder propeller's side force in
the cone |Y| ≤ κ·T (T ≥ 0, within its largest force) or zero lift astern. The tool's factor is a
bisection on its own active-set allocation; the two agree to 0.5 % (issue "Any vessel")."""

import itertools
import math
import os
import random

import pytest
from scipy import optimize  # python3-scipy, installed by scripts/install-deps.sh

import dynpos

SIDES = 32
TOLERANCE = 0.005  # relative, the 0.5 %


def allowed_wedges(forbidden):
    """The complement of the forbidden sectors [deg] as wedges (start, span) [rad], each ≤ π."""
    blocked = []
    for a, b in forbidden:
        if a <= b:
            blocked.append((a, b))
        else:
            blocked += [(a, 360.0), (0.0, b)]
    blocked.sort()
    free, at = [], 0.0
    for a, b in blocked:
        if a > at:
            free.append((at, a))
        at = max(at, b)
    if at < 360.0:
        free.append((at, 360.0))
    # Join the interval that ends at 360° to the one that starts at 0°.
    if len(free) > 1 and free[0][0] == 0.0 and free[-1][1] == 360.0:
        first = free.pop(0)
        last = free.pop()
        free.append((last[0], 360.0 + first[1]))
    wedges = []
    for a, b in free:
        pieces = max(1, math.ceil((b - a) / 180.0 - 1e-12))
        step = (b - a) / pieces
        wedges += [(math.radians(a + i * step), math.radians(step)) for i in range(pieces)]
    return wedges


def regions(unit):
    """Each convex region of a unit as rows (a, b) of a·f ≤ b over its forces f [N]."""
    s = unit["max_thrust_N"]
    if unit["type"] == "azimuth":
        polygon = []
        for j in range(SIDES):
            t = (j + 0.5) * 2.0 * math.pi / SIDES
            polygon.append(((math.cos(t), math.sin(t)), math.cos(math.pi / SIDES) * s))
        if not unit.get("forbidden_deg"):
            return [polygon]
        out = []
        for a, span in allowed_wedges(unit["forbidden_deg"]):
            b = a + span
            out.append(polygon + [((math.sin(a), -math.cos(a)), 0.0),
                                  ((-math.sin(b), math.cos(b)), 0.0)])
        return out
    if unit["type"] in ("tunnel", "propeller"):
        return [[((1.0,), s), ((-1.0,), unit["max_reverse_thrust_N"])]]
    kappa, cap = unit["rudder_lift_per_thrust"], unit["rudder_max_force_N"]
    ahead = [((1.0, 0.0), s), ((-1.0, 0.0), 0.0), ((-kappa, 1.0), 0.0), ((-kappa, -1.0), 0.0)]
    if cap > 0.0:
        ahead += [((0.0, 1.0), cap), ((0.0, -1.0), cap)]
    astern = [((1.0, 0.0), 0.0), ((-1.0, 0.0), unit["max_reverse_thrust_N"]),
              ((0.0, 1.0), 0.0), ((0.0, -1.0), 0.0)]
    return [ahead, astern]


def columns(unit):
    """B's columns of the unit's forces: a surge force at (x, y) gives (1, 0, −y), a side force
    (0, 1, x) (2.2), a rudder's at its own x."""
    x, y = unit["x_m"], unit["y_m"]
    surge, sway = (1.0, 0.0, -y), (0.0, 1.0, x)
    return {"azimuth": [surge, sway], "tunnel": [sway], "propeller": [surge],
            "propeller_rudder": [surge, (0.0, 1.0, unit.get("rudder_x_m", x))]}[unit["type"]]


def lp_factor(units, load, cap=100.0):
    """The largest λ ≤ cap with −λ·load made by forces in one region per unit."""
    best = 0.0
    for combo in itertools.product(*[regions(u) for u in units]):
        n = sum(len(columns(u)) for u in units)
        a_eq = [[0.0] * (n + 1) for _ in range(3)]
        a_ub, b_ub, at = [], [], 0
        for unit, region in zip(units, combo):
            for k, col in enumerate(columns(unit)):
                for r in range(3):
                    a_eq[r][at + k] = col[r]
            for row, bound in region:
                line = [0.0] * (n + 1)
                line[at:at + len(row)] = row
                a_ub.append(line)
                b_ub.append(bound)
            at += len(columns(unit))
        for r in range(3):
            a_eq[r][n] = load[r]  # B·f + λ·load = 0
        c = [0.0] * n + [-1.0]
        bounds = [(None, None)] * n + [(0.0, cap)]
        res = optimize.linprog(c, A_ub=a_ub, b_ub=b_ub, A_eq=a_eq, b_eq=[0.0] * 3,
                               bounds=bounds, method="highs")
        if res.status == 0:
            best = max(best, res.x[n])
    return best


def random_unit(rng, k):
    kind = rng.choice(["azimuth", "azimuth", "tunnel", "propeller", "propeller_rudder"])
    unit = {"name": f"u{k}", "type": kind, "x_m": rng.uniform(-40.0, 40.0),
            "y_m": rng.uniform(-8.0, 8.0), "max_thrust_N": rng.uniform(2e4, 3e5)}
    if kind == "azimuth":
        sectors = []
        for _ in range(rng.randint(0, 2)):
            a = rng.uniform(0.0, 359.0)
            sectors.append((a, (a + rng.uniform(20.0, 90.0)) % 360.0))
        unit["forbidden_deg"] = sectors
        unit["max_reverse_thrust_N"] = 0.0
    elif kind == "propeller_rudder":
        unit["max_reverse_thrust_N"] = 0.7 * unit["max_thrust_N"]
        unit["rudder_lift_per_thrust"] = rng.uniform(0.3, 0.8)
        unit["rudder_max_force_N"] = rng.choice([0.0, 0.3 * unit["max_thrust_N"]])
        unit["rudder_x_m"] = unit["x_m"] - 1.5
    else:
        unit["max_reverse_thrust_N"] = rng.uniform(0.5, 1.0) * unit["max_thrust_N"]
    return unit


def vessel_file(path, units):
    lines = ['name = "random layout"', ""]
    for u in units:
        lines.append("[[thruster]]")
        for key, value in u.items():
            if key == "forbidden_deg":
                if value:
                    lines.append("forbidden_deg = [" +
                                 ", ".join(f"[{a!r}, {b!r}]" for a, b in value) + "]")
            elif isinstance(value, str):
                lines.append(f'{key} = "{value}"')
            else:
                lines.append(f"{key} = {value!r}")
        if u["type"] == "propeller_rudder":
            lines.append("rudder_lift_at_zero_N = 0.0")
        lines.append("")
    path.write_text("\n".join(lines))


def test_the_factor_agrees_with_a_linear_programme(tmp_path):
    rng = random.Random(20261128)
    compared = 0
    for layout in range(30):
        units = [random_unit(rng, k) for k in range(rng.randint(2, 5))]
        vessel = tmp_path / f"layout{layout}.toml"
        vessel_file(vessel, units)
        loads = [(float(i), rng.uniform(-2e5, 2e5), rng.uniform(-2e5, 2e5),
                  rng.uniform(-4e6, 4e6)) for i in range(4)]
        table = tmp_path / f"loads{layout}.csv"
        table.write_text("direction_deg,X_N,Y_N,N_Nm\n" +
                         "".join(f"{d},{x!r},{y!r},{n!r}\n" for d, x, y, n in loads))
        r = dynpos.capability_loads(table, vessel=str(vessel), failure="none")
        for point, (_, x, y, n) in zip(r.points, loads):
            expected = lp_factor(units, (x, y, n))
            got = point.load_factor
            where = f"layout {layout} ({vessel.read_text()}), load {(x, y, n)}"
            if expected >= 100.0:
                assert point.capped, where
                continue
            # A factor whose load is below 1e-3 of the scales is 0 by the tool's rule.
            small = 1e-3 * min(1e5 / max(abs(x), abs(y), 1e-9), 1.3e6 / max(abs(n), 1e-9))
            if expected <= small:
                assert got <= small, where
                continue
            assert got == pytest.approx(expected, rel=TOLERANCE), where
            compared += 1
    assert compared >= 60  # most loads have a factor strictly between 0 and 100
