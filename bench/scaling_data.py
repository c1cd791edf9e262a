"""scaling_data.py — the dimension-scaling benchmark's results as data: which tools run
in which dimension and their labels and colours, the runs file (one JSON object a line:
a "meta" record, then "run" and "skip" records, written by scaling.py), medians per
(dimension, distribution, n, tool), and the slope of log(time) against log(n).
"""

import json
import math
import statistics

# Every tool of `bench_delaunay run`, in table order.
TOOLS = ["lifthull", "lifthull_generic", "cgal_dd", "cgal_2", "cgal_3", "qhull", "tetgen"]
LABEL = {
    "lifthull": "lifthull",
    "lifthull_generic": "lifthull generic",
    "cgal_dd": "CGAL dD",
    "cgal_2": "CGAL DT2",
    "cgal_3": "CGAL DT3",
    "qhull": "Qhull Qt",
    "tetgen": "TetGen",
}
# Okabe-Ito colours (distinguishable with colour blindness); CGAL's two share a hue.
COLOR = {
    "lifthull": "#d55e00",
    "lifthull_generic": "#e69f00",
    "cgal_dd": "#0072b2",
    "cgal_2": "#56b4e9",
    "cgal_3": "#56b4e9",
    "qhull": "#009e73",
    "tetgen": "#cc79a7",
}
DISTS = ["uniform", "grid", "sphere"]
DIST_LABEL = {"uniform": "uniform", "grid": "integer grid", "sphere": "cospherical"}
# lifthull's fixed-dimension engines (lift/insert_delaunay.h): elsewhere lh_delaunay runs the generic
# engine anyway, so a separate "generic" run would measure the same code.
FIXED_DIMS = (2, 3, 4, 5)


def tools_for(d):
    """The tools that serve dimension d, in table order."""
    out = ["lifthull"]
    if d in FIXED_DIMS:
        out.append("lifthull_generic")
    if 2 <= d <= 6:
        out.append("cgal_dd")
    if d == 2:
        out.append("cgal_2")
    if d == 3:
        out.append("cgal_3")
    out.append("qhull")
    if d == 3:
        out.append("tetgen")
    return out


def exact_tool(tool):
    return tool != "qhull"


def fmt_n(n):
    """1000000 -> 10^6, 20000 -> 2·10^4, 1024 -> 1024."""
    m, e = n, 0
    while m >= 10 and m % 10 == 0:
        m, e = m // 10, e + 1
    if e >= 2 and m < 10:
        return ("" if m == 1 else f"{m}·") + f"10^{e}"
    return str(n)


def fmt_s(s):
    if s is None or math.isnan(s):
        return "—"
    if s >= 100:
        return f"{s:.0f}"
    if s >= 10:
        return f"{s:.1f}"
    if s >= 0.1:
        return f"{s:.2f}"
    if s >= 0.001:
        return f"{s:.3f}"
    return f"{s:.2g}"  # 0.00014


def fit_slope(points):
    """Least-squares slope of log y against log x over (x, y) points; None below 2."""
    pts = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y and y > 0]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    if sxx == 0:
        return None
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx


def nlogn_slope(ns):
    """The slope fit_slope gives for t = n log n at these n (slightly above 1)."""
    return fit_slope([(n, n * math.log(n)) for n in ns])


class Results:
    """The records of one sweep, with the lookups the report and the plots need."""

    def __init__(self, records):
        self.meta = next((r for r in records if r.get("kind") == "meta"), {})
        self.runs = [r for r in records if r.get("kind") == "run"]
        self.skips = [r for r in records if r.get("kind") == "skip"]
        self._by = {}
        for r in self.runs:
            self._by.setdefault((r["d"], r["dist"], r["n"], r["tool"]), []).append(r)

    @staticmethod
    def load(path):
        with open(path, encoding="utf-8") as f:
            return Results([json.loads(line) for line in f if line.strip()])

    def configs(self):
        """(d, dist) pairs that have runs, by dimension then distribution order."""
        keys = {(r["d"], r["dist"]) for r in self.runs}
        return sorted(keys, key=lambda k: (k[0], DISTS.index(k[1])))

    def dims(self):
        return sorted({d for d, _ in self.configs()})

    def sizes(self, d, dist):
        return sorted({r["n"] for r in self.runs if r["d"] == d and r["dist"] == dist})

    def ok_runs(self, d, dist, n, tool):
        return [r for r in self._by.get((d, dist, n, tool), []) if r["ok"]]

    def all_runs(self, d, dist, n, tool):
        return self._by.get((d, dist, n, tool), [])

    def median(self, d, dist, n, tool, field="seconds"):
        v = [r[field] for r in self.ok_runs(d, dist, n, tool) if r.get(field) is not None]
        return statistics.median(v) if v else None

    def sites(self, d, dist, n):
        for r in self.runs:
            if r["d"] == d and r["dist"] == dist and r["n"] == n and r.get("sites"):
                return r["sites"]
        return n

    def simplices(self, d, dist, n, tool):
        """The simplex count of the first successful round (None if none)."""
        ok = self.ok_runs(d, dist, n, tool)
        return ok[0]["simplices"] if ok else None

    def skip_reason(self, d, dist, n, tool):
        """Why tool did not run at this size, if it was dropped at or before it."""
        for s in self.skips:
            if s["d"] == d and s["dist"] == dist and s["tool"] == tool and s["n"] <= n:
                return s["reason"]
        return None

    def failures(self):
        return [r for r in self.runs if not r["ok"]]

    def counters(self, d, dist, n):
        """lifthull's predicate counters summed over its rounds, or None."""
        ok = [r for r in self.ok_runs(d, dist, n, "lifthull") if "pred_calls" in r]
        if not ok:
            return None
        keys = ["pred_calls", "pred_filter", "pred_grid", "pred_residue", "pred_exact",
                "pred_zero", "pred_sos_general"]
        tot = {k: sum(r.get(k, 0) for r in ok) for k in keys}
        tot["rounds"] = len(ok)
        return tot

    def time_points(self, d, dist, tool, floor=1e-3):
        """(sites, median seconds) per size, leaving out times below floor (timer noise)."""
        out = []
        for n in self.sizes(d, dist):
            t = self.median(d, dist, n, tool)
            if t is not None and t >= floor:
                out.append((self.sites(d, dist, n), t))
        return out
