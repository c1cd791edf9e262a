"""scaling_report.py — writes docs/benchmarks.md from the scaling sweep's results
(scaling_data.Results): provenance and machine, the protocol, the time plot with the
slope of log t against log n per tool (is it n log n?), a table per dimension, simplices
per second, peak memory, lifthull's exact-path fraction of predicate calls, simplex-count
agreement, and the runs that were skipped or failed. Returns the exit status: 2 if a run
failed (other than by the time limit) or an exact tool's simplex count differed from
lifthull's on uniform sites.
"""

import math

import scaling_data as sd
import scaling_plots

# |slope - n log n's slope| up to this is called "as n log n".
SLOPE_TOLERANCE = 0.15


def _ratio(t, ref):
    return f" ({t / ref:.2f}x)" if t and ref else ""


def _pct(part, whole):
    if not whole:
        return "—"
    p = 100.0 * part / whole
    if p == 0:
        return "0"
    return f"{p:.3g}%" if p >= 0.01 else f"{p:.1e}%"


def _tools(res, d):
    built = res.meta.get("tools", sd.TOOLS)
    return [t for t in sd.tools_for(d) if t in built]


def _cell(res, d, dist, n, tool, ref):
    t = res.median(d, dist, n, tool)
    if t is not None:
        return sd.fmt_s(t) + ("" if tool == "lifthull" else _ratio(t, ref))
    if res.skip_reason(d, dist, n, tool):
        return "skipped"
    if res.all_runs(d, dist, n, tool):
        return "**failed**"
    return "—"


def _head(res, out):
    m = res.meta
    if m.get("quick"):
        out += ["> **Placeholder from a `--quick` smoke run**: tiny sizes, a budget of "
                f"{m.get('budget', 0):g} s per run. It shows what the report contains, not how "
                "lifthull scales: timings of milliseconds are noise, and the slopes below are "
                "fitted over sizes too small to mean anything. Run `bash bench/run_scaling.sh` "
                "(without --quick) for the real figures.", ""]
    total = m.get("seconds")
    total_s = f"; the sweep took {total / 60:.1f} min" if total else ""
    build = m.get("build_dir") or "build-bench/"
    out += [f"Produced by `{m.get('command', 'bash bench/run_scaling.sh')}` on "
            f"{m.get('date', '?')} (Release build in {build}, git commit "
            f"{m.get('commit', '?')}{total_s}). Raw data, every run: "
            "[bench-scaling-runs.csv](bench-scaling-runs.csv). Source: bench/run_scaling.sh, "
            "bench/scaling*.py, bench/bench_delaunay.cpp, bench/bench_sites.cpp.", ""]
    out += ["## Machine and build", ""]
    out += m.get("facts", ["- (facts not recorded)"])
    left_out = [sd.LABEL[t] for t in sd.TOOLS if t not in m.get("tools", sd.TOOLS)]
    if left_out:
        out.append(f"- **not built, left out**: {', '.join(left_out)}")
    out.append("")


def _protocol(res, out):
    m = res.meta
    out += ["## Protocol and inputs", "",
            f"- Every run is a separate process, `bench_delaunay run TOOL D N SEED --dist DIST`, "
            "that generates the sites, triangulates them once and reports its wall time, simplex "
            "count and peak memory. For each size, "
            f"{m.get('rounds', '?')} interleaved rounds: round r runs every tool once, in an "
            f"order rotated by r, on the sites of seed {m.get('seed', '?')}+r. Each figure is "
            "the median over the rounds; ratios are tool / lifthull (2.0x: lifthull took half "
            "the time).",
            f"- Time budget: a tool whose median exceeds {m.get('budget', 0):g} s at one size, "
            "or whose time extrapolated to the next size (from its last two sizes' slope, at "
            f"least linear) exceeds {2 * m.get('budget', 0):g} s, is not run at the larger sizes "
            "of that dimension and distribution (\"skipped\" in the tables, reasons at the end); "
            f"a run is killed after {m.get('timeout', 0):g} s.",
            "- **uniform**: n sites uniform in [0,1)^d (53-bit doubles from xoshiro256**, "
            "tools/sites.h).",
            "- **integer grid**: all k^d points of {0,..,k-1}^d, k = round(n^(1/d)), in a "
            "seeded random order: the column *n* gives k^d. Every unit square (cube) is "
            "cospherical: maximal degeneracy, resolved exactly by lifthull and CGAL.",
            "- **cospherical**: n distinct integer points exactly on one sphere about the "
            "origin (exact in doubles), a seeded random subset of all the lattice points of "
            "a sphere |x|^2 = M chosen to hold at least n, in random order: the exactly "
            "cospherical sites of tools/sites.h (as `lifthull points --exact-sphere`; in 2D M "
            "a product of primes 1 mod 4, at most 1105920 sites; in 3D at most 10^7). Every "
            "triangulation of such sites is Delaunay; the exact tools pick one by their "
            "perturbation, so from 3D on simplex counts may differ between tools. Qhull "
            "runs with `Qz` added (it refuses cospherical input under `Qbb` without it).",
            "- Time: from the sites in the tool's input form to the triangulation built and "
            "its finite simplices counted (lifthull: `lh_delaunay` with its canonical output; "
            "CGAL: range insert; Qhull: `qhull d Qbb Qt Qc` through libqhull_r, i.e. "
            "`qdelaunay Qt`; TetGen: `tetrahedralize(\"Q\")`); see "
            "[bench-delaunay.md](bench-delaunay.md) for the details. *lifthull* is the "
            "fixed-dimension path (d = 2..5; from 6D on, `lh_delaunay` runs the generic engine, "
            "so no separate generic run); *lifthull generic* is `lh_options.generic_engine`.",
            "- Peak memory: whole-process maximum RSS, including the program, the libraries "
            "and the input; *input only* is a run that just generates the sites.", ""]


def _slope_verdict(s, ref):
    if s is None:
        return None
    if abs(s - ref) <= SLOPE_TOLERANCE:
        return "as n log n"
    return "slower than n log n" if s > ref else "below n log n (fixed costs at small n)"


def _slopes(res, out):
    out += ["## Time against n", "", f"![Median time against n]({scaling_plots.TIME_SVG})", ""]
    rows, verdicts = [], {}
    tools_all = [t for t in sd.TOOLS if any(t in _tools(res, d) for d in res.dims())]
    for d, dist in res.configs():
        cells, ref = [], None
        for t in tools_all:
            if t not in _tools(res, d):
                cells.append("—")
                continue
            pts = res.time_points(d, dist, t)
            s = sd.fit_slope(pts)
            if s is None:
                cells.append("—")
                continue
            ref = sd.nlogn_slope([n for n, _ in pts])
            v = _slope_verdict(s, ref)
            verdicts.setdefault((t, v), []).append(f"{d}D {dist} {s:.2f}")
            cells.append(f"{s:.2f}" + ("" if len(pts) > 2 else "²") +
                         ("" if v == "as n log n" else " *"))
        ns = [res.sites(d, dist, n) for n in res.sizes(d, dist)]
        ref_all = sd.nlogn_slope(ns)
        k_pts = [(res.sites(d, dist, n), res.simplices(d, dist, n, "lifthull"))
                 for n in res.sizes(d, dist)]
        k_slope = sd.fit_slope([(n, k) for n, k in k_pts if k])
        rows.append(f"| {d} | {sd.DIST_LABEL[dist]} | {sd.fmt_n(ns[0])}..{sd.fmt_n(ns[-1])} | "
                    + (f"{ref_all:.2f}" if ref_all else "—") + " | "
                    + (f"{k_slope:.2f}" if k_slope else "—") + " | " + " | ".join(cells) + " |")
    out += ["Does the time grow as n log n? The slope of log(time) against log(n), fitted by "
            "least squares over each tool's sizes (times under 1 ms left out), beside the "
            "slope n log n itself has over the same sizes (slightly above 1; n² would give 2) "
            "and the slope of lifthull's simplex count (the output's own growth). "
            f"`*`: more than {SLOPE_TOLERANCE} away from n log n's; `²`: fitted over two sizes "
            "only.", ""]
    out.append("| D | sites | n range | n log n | simplex count | " +
               " | ".join(sd.LABEL[t] for t in tools_all) + " |")
    out.append("|---:|---|---|---:|---:|" + "---:|" * len(tools_all))
    out += rows
    out.append("")
    for t in tools_all:
        parts = []
        for v in ("as n log n", "below n log n (fixed costs at small n)", "slower than n log n"):
            cases = verdicts.get((t, v))
            if cases:
                parts.append(f"{v} in {', '.join(cases)}")
        if parts:
            out.append(f"- **{sd.LABEL[t]}**: " + "; ".join(parts) + ".")
    out += ["", "A time slope above n log n's where the simplex count's slope is above 1 too "
            "comes from the output itself: in 5D and up the number of simplices per uniform "
            "site in a cube still grows with n (a smaller share of the sites lies near the "
            "boundary); time per simplex is then the fairer measure (the per-dimension tables "
            "give simplices per second).", ""]


def _dimension_tables(res, out):
    out += ["## Per dimension", "",
            "Median seconds (ratio tool / lifthull), lifthull's peak memory and its bytes per "
            "site above the input-only run, and lifthull's simplices per second.", ""]
    for d in res.dims():
        tools = _tools(res, d)
        out += [f"### {d}D", ""]
        out.append("| sites | n | " + " | ".join(sd.LABEL[t] for t in tools) +
                   " | lifthull MiB | bytes/site | simplices | Msimplices/s |")
        out.append("|---|---:|" + "---:|" * (len(tools) + 4))
        for dist in sd.DISTS:
            sizes = res.sizes(d, dist)
            for n in sizes:
                ref = res.median(d, dist, n, "lifthull")
                cells = [_cell(res, d, dist, n, t, ref) for t in tools]
                sites = res.sites(d, dist, n)
                peak = res.median(d, dist, n, "lifthull", "peak_kb")
                base = res.median(d, dist, n, "none", "peak_kb")
                mib = f"{peak / 1024:.1f}" if peak else "—"
                bps = f"{(peak - base) * 1024 / sites:.0f}" if peak and base else "—"
                k = res.simplices(d, dist, n, "lifthull")
                rate = f"{k / ref / 1e6:.2f}" if k and ref else "—"
                out.append(f"| {sd.DIST_LABEL[dist]} | {sd.fmt_n(sites)} | " + " | ".join(cells) +
                           f" | {mib} | {bps} | {k if k else '—'} | {rate} |")
        out.append("")


def _rate(res, out):
    out += ["## Simplices per second", "", f"![Simplices per second]({scaling_plots.RATE_SVG})",
            "", "Uniform sites, at the largest n lifthull ran in each dimension: each tool's own "
            "simplex count over its median time (millions per second; — where the tool was "
            "skipped at that size or does not serve the dimension).", ""]
    tools = [t for t in sd.TOOLS if any(t in _tools(res, d) for d in res.dims())]
    out.append("| D | n | simplices | simplices/site | " +
               " | ".join(sd.LABEL[t] for t in tools) + " |")
    out.append("|---:|---:|---:|---:|" + "---:|" * len(tools))
    rates = {t: {d: r for d, r, _ in scaling_plots.rate_points(res, t)} for t in tools}
    for d, _, n in scaling_plots.rate_points(res, "lifthull"):
        k = res.simplices(d, "uniform", n, "lifthull")
        sites = res.sites(d, "uniform", n)
        cells = [f"{rates[t][d] / 1e6:.3g}" if rates[t].get(d) else "—" for t in tools]
        out.append(f"| {d} | {sd.fmt_n(sites)} | {k} | {k / sites:.1f} | " + " | ".join(cells) + " |")
    out.append("")


def _memory(res, out):
    out += ["## Peak memory", "", f"![Peak memory against n]({scaling_plots.MEMORY_SVG})", "",
            "Median peak MiB at the largest size of each dimension and distribution that "
            "lifthull ran (ratio tool / lifthull):", ""]
    tools = [t for t in sd.TOOLS if any(t in _tools(res, d) for d in res.dims())]
    out.append("| D | sites | n | input only | " + " | ".join(sd.LABEL[t] for t in tools) + " |")
    out.append("|---:|---|---:|---:|" + "---:|" * len(tools))
    for d, dist in res.configs():
        sizes = [n for n in res.sizes(d, dist) if res.median(d, dist, n, "lifthull", "peak_kb")]
        if not sizes:
            continue
        n = sizes[-1]
        ref = res.median(d, dist, n, "lifthull", "peak_kb")
        cells = []
        for t in tools:
            k = res.median(d, dist, n, t, "peak_kb") if t in _tools(res, d) else None
            cells.append(f"{k / 1024:.1f}" + ("" if t == "lifthull" else _ratio(k, ref)) if k else "—")
        base = res.median(d, dist, n, "none", "peak_kb")
        out.append(f"| {d} | {sd.DIST_LABEL[dist]} | {sd.fmt_n(res.sites(d, dist, n))} | "
                   f"{base / 1024 if base else 0:.1f} | " + " | ".join(cells) + " |")
    out.append("")


def _exact_fraction(res, out):
    out += ["## lifthull's predicates: how often the exact stage ran", "",
            "Every orientation and insphere decision of `lh_delaunay` (the fixed-dimension "
            "engines' inline filters included) is counted by the stage that settled it "
            "(`lh_pred_counters`, summed over the rounds): the floating-point *filter*; the "
            "filter's *grid* bound, which certifies an exact zero without exact arithmetic "
            "when the coordinates lie on a common grid; *residues*, which prove an exact "
            "zero modulo machine-word moduli; or the multi-limb *exact* integer stage. "
            "*Zero*: unperturbed answer exactly 0, which the symbolic perturbation then "
            "decides (*SoS general*: by its slower general search).", ""]
    out.append("| D | sites | n | calls per site | filter | grid | residues | **exact stage** | "
               "zero | SoS general |")
    out.append("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    worst = {}
    for d, dist in res.configs():
        for n in res.sizes(d, dist):
            c = res.counters(d, dist, n)
            if not c or not c["pred_calls"]:
                continue
            sites = res.sites(d, dist, n)
            calls = c["pred_calls"]
            frac = c["pred_exact"] / calls
            worst[dist] = max(worst.get(dist, (0, "")), (frac, f"{d}D n={sd.fmt_n(sites)}"))
            out.append(f"| {d} | {sd.DIST_LABEL[dist]} | {sd.fmt_n(sites)} | "
                       f"{calls / c['rounds'] / sites:.0f} | {_pct(c['pred_filter'], calls)} | "
                       f"{_pct(c['pred_grid'], calls)} | {_pct(c.get('pred_residue', 0), calls)} | "
                       f"**{_pct(c['pred_exact'], calls)}** | "
                       f"{_pct(c['pred_zero'], calls)} | {_pct(c['pred_sos_general'], calls)} |")
    out.append("")
    if worst:
        out.append("Largest exact-stage fraction per distribution: " + "; ".join(
            f"{sd.DIST_LABEL[k]} {100 * v[0]:.3g}% ({v[1]})" if v[0] else
            f"{sd.DIST_LABEL[k]} none (no call needed it)" for k, v in worst.items()) + ".")
        out.append("")


def _counts(res, out):
    """Simplex counts: on uniform sites every exact tool must match lifthull in every
    round; on degenerate sites counts may differ (any triangulation of cospherical sites
    is Delaunay). Returns the number of exact mismatches on uniform sites."""
    exact_bad, inexact_bad = [], []
    for d, dist in res.configs():
        if dist != "uniform":
            continue
        for n in res.sizes(d, dist):
            by_seed = {}
            for t in _tools(res, d):
                for r in res.ok_runs(d, dist, n, t):
                    by_seed.setdefault(r["seed"], {})[t] = r["simplices"]
            for seed, counts in sorted(by_seed.items()):
                ref = counts.get("lifthull")
                for t, k in counts.items():
                    if ref is not None and k != ref:
                        msg = f"{d}D n={sd.fmt_n(n)} seed {seed}: {sd.LABEL[t]} {k}, lifthull {ref}"
                        (exact_bad if sd.exact_tool(t) else inexact_bad).append(msg)
    out += ["## Simplex counts", ""]
    if not exact_bad and not inexact_bad:
        out.append("Uniform sites: every tool counted the same simplices as lifthull in every "
                   "round.")
    else:
        out.append(f"Uniform sites: **{len(exact_bad) + len(inexact_bad)} disagreement(s)**:")
        out.append("")
        out += [f"- exact tool: {m}" for m in exact_bad]
        out += [f"- Qhull (not exact): {m}" for m in inexact_bad]
    degenerate = [(d, dist) for d, dist in res.configs() if dist != "uniform"]
    if degenerate:
        tools = [t for t in sd.TOOLS if any(t in _tools(res, d) for d, _ in degenerate)]
        out += ["", "Degenerate sites (first round): every triangulation of a cospherical "
                "subset is Delaunay, so counts legitimately differ from 3D on (in 2D they are "
                "fixed by the hull: 2n - h - 2). Qhull `Qt` may also emit flat simplices or "
                "leave out sites it merged as coplanar.", ""]
        out.append("| D | sites | n | " + " | ".join(sd.LABEL[t] for t in tools) + " |")
        out.append("|---:|---|---:|" + "---:|" * len(tools))
        for d, dist in degenerate:
            for n in res.sizes(d, dist):
                cells = []
                for t in tools:
                    k = res.simplices(d, dist, n, t) if t in _tools(res, d) else None
                    cells.append(str(k) if k is not None else "—")
                out.append(f"| {d} | {sd.DIST_LABEL[dist]} | {sd.fmt_n(res.sites(d, dist, n))} | "
                           + " | ".join(cells) + " |")
    out.append("")
    return len(exact_bad)


def _skips(res, out):
    fails = res.failures()
    if not res.skips and not fails:
        return
    out += ["## Skipped and failed runs", ""]
    for s in res.skips:
        out.append(f"- {sd.LABEL.get(s['tool'], s['tool'])}, {s['d']}D {sd.DIST_LABEL[s['dist']]}, "
                   f"n >= {sd.fmt_n(s['n'])}: skipped: {s['reason']}")
    for r in fails:
        out.append(f"- {sd.LABEL.get(r['tool'], r['tool'])}, {r['d']}D "
                   f"{sd.DIST_LABEL[r['dist']]}, n = {sd.fmt_n(r['n'])}, seed {r['seed']}: "
                   f"**{r.get('error', 'failed')}**")
    out.append("")


def write(res, path):
    out = ["# Dimension-scaling benchmark: lifthull against CGAL, Qhull and TetGen, 2D-8D", ""]
    _head(res, out)
    _protocol(res, out)
    _slopes(res, out)
    _dimension_tables(res, out)
    _rate(res, out)
    _memory(res, out)
    _exact_fraction(res, out)
    bad = _counts(res, out)
    _skips(res, out)
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out).rstrip() + "\n")
    failed_runs = [r for r in res.failures()
                   if not r.get("error", "").startswith("timeout")]
    return 2 if bad or failed_runs else 0
