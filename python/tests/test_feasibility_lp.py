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


def loss_factor(loss, alpha):
    """The factor at direction alpha [rad]: linear between the table's points round the circle."""
    a = math.degrees(alpha) % 360.0
    before = [p for p in loss if p[0] <= a]
    p = before[-1] if before else loss[-1]
    q = loss[(loss.index(p) + 1) % len(loss)]
    span = (q[0] - p[0]) % 360.0
    return p[1] if span == 0.0 else p[1] + (q[1] - p[1]) * ((a - p[0]) % 360.0) / span


def wedge_rows(a, b):
    """Directions from a to b [rad] (b − a ≤ π): not before a, not after b."""
    return [((math.sin(a), -math.cos(a)), 0.0), ((-math.sin(b), math.cos(b)), 0.0)]


def loss_regions(unit):
    """An azimuth with a loss table: the triangles (origin, corner j, corner j+1) of its polygon,
    each corner at its factor, cut by each allowed wedge: their union is the star polygon."""
    s, out = unit["max_thrust_N"], []
    for j in range(SIDES):
        t0, t1 = j * 2.0 * math.pi / SIDES, (j + 1) * 2.0 * math.pi / SIDES
        v0 = [s * loss_factor(unit["loss"], t0) * f for f in (math.cos(t0), math.sin(t0))]
        v1 = [s * loss_factor(unit["loss"], t1) * f for f in (math.cos(t1), math.sin(t1))]
        d = (v1[0] - v0[0], v1[1] - v0[1])
        length = math.hypot(*d)
        chord = ((d[1] / length, -d[0] / length), (d[1] * v0[0] - d[0] * v0[1]) / length)
        for a, span in allowed_wedges(unit.get("forbidden_deg") or []):
            # The triangle's directions [t0, t1] within the wedge [a, a + span], if any.
            for shift in (0.0, 2.0 * math.pi, -2.0 * math.pi):
                lo, hi = max(t0, a + shift), min(t1, a + span + shift)
                if hi - lo > 1e-12:
                    out.append([chord] + wedge_rows(lo, hi))
    return out


def regions(unit):
    """Each convex region of a unit as rows (a, b) of a·f ≤ b over its forces f [N]."""
    s = unit["max_thrust_N"]
    if unit["type"] == "azimuth" and unit.get("loss"):
        return loss_regions(unit)
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
            if key == "loss":
                if value:
                    lines.append("loss = [" + ", ".join(f"[{a!r}, {b!r}]" for a, b in value) + "]")
            elif key == "forbidden_deg":
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


def compared_points(vessel, table, units, loads):
    """The tool's factor of each load against the linear programme's: the number compared
    strictly between 0 and 100 (the others are checked for the cap or for nothing held)."""
    r = dynpos.capability_loads(table, vessel=str(vessel), failure="none")
    compared = 0
    for point, (_, x, y, n) in zip(r.points, loads):
        expected = lp_factor(units, (x, y, n))
        where = f"{vessel.read_text()}, load {(x, y, n)}"
        if expected >= 100.0:
            assert point.capped, where
            continue
        # A factor whose load is below 1e-3 of the scales is 0 by the tool's rule.
        small = 1e-3 * min(1e5 / max(abs(x), abs(y), 1e-9), 1.3e6 / max(abs(n), 1e-9))
        if expected <= small:
            assert point.load_factor <= small, where
            continue
        assert point.load_factor == pytest.approx(expected, rel=TOLERANCE), where
        compared += 1
    return compared


def load_table(path, loads):
    path.write_text("direction_deg,X_N,Y_N,N_Nm\n" +
                    "".join(f"{d},{x!r},{y!r},{n!r}\n" for d, x, y, n in loads))
    return path


def test_the_factor_agrees_with_a_linear_programme(tmp_path):
    rng = random.Random(20261128)
    compared = 0
    for layout in range(30):
        units = [random_unit(rng, k) for k in range(rng.randint(2, 5))]
        vessel = tmp_path / f"layout{layout}.toml"
        vessel_file(vessel, units)
        loads = [(float(i), rng.uniform(-2e5, 2e5), rng.uniform(-2e5, 2e5),
                  rng.uniform(-4e6, 4e6)) for i in range(4)]
        table = load_table(tmp_path / f"loads{layout}.csv", loads)
        compared += compared_points(vessel, table, units, loads)
    assert compared >= 60  # most loads have a factor strictly between 0 and 100


def test_the_factor_with_a_loss_table_agrees_with_a_linear_programme(tmp_path):
    """One azimuth of each layout with a dip in its thrust (30–70 % across 20–80°): the star
    polygon as 32 triangles (the LP's regions) against the tool's convex fans."""
    rng = random.Random(20261129)
    compared = 0
    for layout in range(8):
        units = [random_unit(rng, k) for k in range(rng.randint(2, 4))]
        centre, half = rng.uniform(40.0, 320.0), rng.uniform(10.0, 40.0)
        units[0] = {"name": "u0", "type": "azimuth", "x_m": rng.uniform(-40.0, 40.0),
                    "y_m": rng.uniform(-8.0, 8.0), "max_thrust_N": rng.uniform(5e4, 3e5),
                    "forbidden_deg": [], "max_reverse_thrust_N": 0.0,
                    "loss": [(centre - half, 1.0), (centre, rng.uniform(0.3, 0.7)),
                             (centre + half, 1.0)]}
        for u in units[1:]:  # one non-convex region at a time keeps the programmes few
            u.pop("forbidden_deg", None)
        vessel = tmp_path / f"loss{layout}.toml"
        vessel_file(vessel, units)
        loads = [(float(i), rng.uniform(-2e5, 2e5), rng.uniform(-2e5, 2e5),
                  rng.uniform(-4e6, 4e6)) for i in range(3)]
        table = load_table(tmp_path / f"lossloads{layout}.csv", loads)
        compared += compared_points(vessel, table, units, loads)
    assert compared >= 10
