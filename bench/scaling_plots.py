"""scaling_plots.py — the three figures of docs/benchmarks.md, drawn with svg_plot.py:
bench-scaling-time.svg (median time against n, a log-log panel per dimension and
distribution, a line per tool), bench-scaling-rate.svg (simplices per second against the
dimension, uniform sites) and bench-scaling-memory.svg (peak memory against n, panels as
the time plot's).
"""

import os

import scaling_data as sd
import svg_plot

TIME_SVG = "bench-scaling-time.svg"
RATE_SVG = "bench-scaling-rate.svg"
MEMORY_SVG = "bench-scaling-memory.svg"
INPUT_COLOR = "#999999"
# CGAL's DT2 (2D only) and DT3 (3D only) share a colour and a legend entry.
PLOT_LABEL = dict(sd.LABEL, cgal_2="CGAL DT2/DT3", cgal_3="CGAL DT2/DT3")
SUPERSCRIPT = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def _n_text(n):
    """sd.fmt_n with a real superscript: 10⁶, 2·10⁴."""
    head, _, exp = sd.fmt_n(n).partition("^")
    return head + exp.translate(SUPERSCRIPT)


def _tools_present(res, configs):
    present = {r["tool"] for r in res.runs if r["ok"] and (r["d"], r["dist"]) in configs}
    return [t for t in sd.TOOLS if t in present]


def _legend(tools, with_input=False):
    out = []
    for t in tools:
        entry = (PLOT_LABEL[t], sd.COLOR[t], t == "lifthull_generic")
        if entry not in out:
            out.append(entry)
    if with_input:
        out.append(("input only", INPUT_COLOR, True))
    return out


def _panels(res, field, scale, with_input):
    """A panel per (d, dist): per tool the median of field (times scale) against sites."""
    panels = []
    for d, dist in res.configs():
        series = []
        tools = sd.tools_for(d) + (["none"] if with_input else [])
        for t in tools:
            pts = []
            for n in res.sizes(d, dist):
                v = res.median(d, dist, n, t, field)
                if v is not None and v > 0:
                    pts.append((res.sites(d, dist, n), v * scale))
            if pts:
                color = INPUT_COLOR if t == "none" else sd.COLOR[t]
                series.append(svg_plot.Series(PLOT_LABEL.get(t, "input only"), pts, color,
                                              dashed=t in ("lifthull_generic", "none")))
        ylabel = "seconds" if field == "seconds" else "peak MiB"
        panels.append(svg_plot.Panel(f"{d}D, {sd.DIST_LABEL[dist]}", series, "sites n", ylabel))
    return panels


def rate_points(res, tool):
    """(d, simplices per second) on uniform sites at the largest n lifthull ran in each
    dimension; the tool's own simplex count and median time there (None: not run)."""
    out = []
    for d in res.dims():
        sizes = [n for n in res.sizes(d, "uniform") if res.median(d, "uniform", n, "lifthull")]
        if not sizes:
            continue
        n = sizes[-1]
        t, k = res.median(d, "uniform", n, tool), res.simplices(d, "uniform", n, tool)
        out.append((d, k / t if t and k else None, n))
    return out


def write_all(res, docs):
    configs = res.configs()
    if not configs:
        return
    tools = _tools_present(res, set(configs))
    cols = 4 if len(configs) > 9 else 3
    svg_plot.write(os.path.join(docs, TIME_SVG),
                   "Delaunay triangulation: median time against n (log-log)",
                   _panels(res, "seconds", 1.0, False), _legend(tools), cols=cols,
                   note="each point: the median of the rounds, every run a separate process")
    svg_plot.write(os.path.join(docs, MEMORY_SVG),
                   "Peak memory (whole-process maximum RSS) against n (log-log)",
                   _panels(res, "peak_kb", 1.0 / 1024.0, True), _legend(tools, True), cols=cols,
                   note="input only: a run that just generates the sites")
    series, dims, shown = [], res.dims(), []
    for t in tools:
        if t == "cgal_3" and "cgal_2" in tools:
            continue  # drawn with cgal_2 as one line
        pts = [(d, r) for d, r, _ in rate_points(res, t)]
        if t == "cgal_2":  # one line: DT2's 2D point, DT3's 3D point
            dt3 = dict((d, r) for d, r, _ in rate_points(res, "cgal_3"))
            pts = [(d, r if d == 2 else dt3.get(d)) for d, r in pts]
        if any(r for _, r in pts):
            series.append(svg_plot.Series(PLOT_LABEL[t], pts, sd.COLOR[t],
                                          dashed=t == "lifthull_generic"))
            shown.append(t)
    sizes = ", ".join(f"{d}D {_n_text(n)}" for d, _, n in rate_points(res, "lifthull"))
    panel = svg_plot.Panel("uniform sites, at the largest n lifthull ran per dimension", series,
                           "dimension d", "simplices per second", xlog=False, ylog=True,
                           xticks=[(d, str(d)) for d in dims])
    svg_plot.write(os.path.join(docs, RATE_SVG), "Simplices per second against the dimension",
                   [panel], _legend(shown),
                   cols=1, panel_w=620, panel_h=330, note=f"n: {sizes}")
