#!/usr/bin/env python3
"""scaling.py — the dimension-scaling sweep behind bench/run_scaling.sh: runs
`bench_delaunay run TOOL D N SEED --dist DIST` for every tool that serves D, over sizes N
per (D, distribution), each run a separate process; R interleaved rounds per size (round
r runs every tool once, in an order rotated by r, on seed S+r), so that a slow minute of
a shared machine hits every tool alike. A tool whose median exceeds the time budget at
one size, or whose time extrapolated to the next size exceeds twice the budget, is not
run at the larger sizes of that (D, distribution); the report says so. Every run is
appended to a JSON-lines file as it ends (--resume continues an interrupted sweep from
it), then scaling_report.py writes the Markdown and scaling_plots.py the SVG plots.
Progress on stderr. Exit status 0, or 2 if a run failed (other than by the time limit)
or the exact tools disagreed on uniform sites.
"""

import argparse
import csv
import datetime
import json
import math
import os
import signal
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scaling_data as sd  # noqa: E402
import scaling_plots  # noqa: E402
import scaling_report  # noqa: E402

# Sizes per distribution and dimension. Full sweep: decades, with intermediate points
# where a decade is the whole range; 7D and 8D stop at 10^3 (Delaunay's size grows fast
# with d: 8D, 10^3 uniform sites give millions of simplices). The degenerate families
# run in 2D-4D; cospherical sizes stay within tools/sites.h's generator (2D: 1105920
# sites, 3D: 10^7).
FULL = {
    "uniform": {2: [10**3, 10**4, 10**5, 10**6], 3: [10**3, 10**4, 10**5, 10**6],
                4: [10**3, 10**4, 10**5], 5: [10**3, 10**4, 2 * 10**4, 10**5],
                6: [10**3, 3000, 10**4], 7: [100, 300, 1000], 8: [100, 300, 1000]},
    "grid": {2: [10**3, 10**4, 10**5, 10**6], 3: [10**3, 10**4, 10**5, 10**6],
             4: [10**3, 10**4, 10**5]},
    "sphere": {2: [10**3, 10**4, 10**5, 10**6], 3: [10**3, 10**4, 10**5, 10**6], 4: [10**3, 10**4, 10**5]},
}
# --quick: a smoke run of the whole pipeline in about a minute; its times mean little.
QUICK = {
    "uniform": {2: [100, 1000, 10**4], 3: [100, 1000, 10**4], 4: [100, 1000],
                5: [100, 300], 6: [50, 100], 7: [30, 50], 8: [20, 30]},
    "grid": {2: [100, 1000, 10**4], 3: [100, 1000, 3000], 4: [100, 500]},
    "sphere": {2: [100, 1000, 10**4], 3: [100, 1000, 3000], 4: [100, 500]},
}


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True, help="the bench_delaunay executable")
    ap.add_argument("--out", required=True, help="the Markdown report to write")
    ap.add_argument("--results", required=True, help="the JSON-lines runs file")
    ap.add_argument("--quick", action="store_true", help="tiny sizes: a smoke run")
    ap.add_argument("--rounds", type=int, default=3, help="interleaved rounds (default 3)")
    ap.add_argument("--dims", default="2,3,4,5,6,7,8", help="dimensions, e.g. 2,3")
    ap.add_argument("--dists", default="uniform,grid,sphere", help="site distributions")
    ap.add_argument("--budget", type=float, default=None,
                    help="seconds a run may take before the tool is dropped at larger "
                         "sizes (default 60; --quick 1)")
    ap.add_argument("--timeout", type=float, default=None,
                    help="seconds after which a run is killed (default 4 budgets)")
    ap.add_argument("--seed", type=int, default=20240611, help="seed of round 0")
    ap.add_argument("--resume", action="store_true",
                    help="keep the runs already in --results and do only the missing ones")
    ap.add_argument("--report-only", action="store_true",
                    help="no runs: rewrite the report and plots from --results")
    ap.add_argument("--commit", default="unknown", help="git commit, for the report")
    ap.add_argument("--build-dir", default="", help="build directory, for the report")
    ap.add_argument("--command", default="bash bench/run_scaling.sh",
                    help="the command line, for the report")
    a = ap.parse_args(argv)
    a.dims = [int(x) for x in a.dims.split(",") if x]
    a.dists = [x for x in a.dists.split(",") if x]
    for x in a.dists:
        if x not in sd.DISTS:
            ap.error(f"unknown distribution {x} (uniform, grid, sphere)")
    for d in a.dims:
        if not 2 <= d <= 8:
            ap.error(f"dimension {d} outside 2..8")
    if a.rounds < 1:
        ap.error("--rounds must be at least 1")
    if a.budget is None:
        a.budget = 1.0 if a.quick else 60.0
    if a.timeout is None:
        a.timeout = max(10.0, 4 * a.budget)
    return a


def run_once(exe, tool, d, n, seed, dist, timeout):
    """One child process; returns the run record (ok False with an error on failure)."""
    rec = {"kind": "run", "tool": tool, "d": d, "dist": dist, "n": n, "seed": seed,
           "ok": False}
    cmd = [exe, "run", tool, str(d), str(n), str(seed), "--dist", dist,
           "--timeout", str(int(math.ceil(timeout)))]
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout + 30)
    except subprocess.TimeoutExpired:
        rec["error"] = f"timeout (> {timeout:.0f} s)"
        return rec
    if p.returncode != 0:
        if p.returncode == -signal.SIGALRM:
            rec["error"] = f"timeout (> {timeout:.0f} s)"
        else:
            last = (p.stderr.strip().splitlines() or [""])[-1][:200]
            rec["error"] = f"exit status {p.returncode}: {last}"
        return rec
    fields = dict(tok.split("=", 1) for tok in p.stdout.split() if "=" in tok)
    for k, v in fields.items():
        rec[k] = float(v) if k in ("seconds", "cpu", "hull_seconds") else int(v)
    rec["ok"] = "seconds" in rec
    if not rec["ok"]:
        rec["error"] = "unparsable output: " + p.stdout[:200]
    return rec


def built_tools(exe):
    """Tools whose library was found at configure time: Qhull and TetGen are optional."""
    out = []
    for t in sd.TOOLS:
        d = 3 if t in ("cgal_3", "tetgen") else 2
        rec = run_once(exe, t, d, 20, 1, "uniform", 30)
        if rec["ok"]:
            out.append(t)
        else:
            print(f"scaling: {t} left out ({rec.get('error')})", file=sys.stderr)
    return out


def predicted(points, n_next):
    """Time at n_next extrapolated from (n, t) points: the last two sizes' slope (at
    least 1), or n log n from a single size."""
    n1, t1 = points[-1]
    if len(points) >= 2:
        n0, t0 = points[-2]
        s = max(1.0, math.log(t1 / t0) / math.log(n1 / n0)) if t0 > 0 and t1 > 0 else 1.0
        return t1 * (n_next / n1) ** s
    return t1 * (n_next * math.log(n_next)) / (n1 * math.log(n1))


class Sweep:
    def __init__(self, args, tools, out):
        self.a, self.tools, self.out = args, tools, out
        self.done = {}  # (tool, d, dist, n, seed) -> record, from --resume
        self.records = []

    def emit(self, rec):
        self.records.append(rec)
        self.out.write(json.dumps(rec) + "\n")
        self.out.flush()

    def run(self, tool, d, dist, n, seed):
        key = (tool, d, dist, n, seed)
        kept = key in self.done
        rec = self.done[key] if kept else run_once(self.a.exe, tool, d, n, seed, dist,
                                                   self.a.timeout)
        self.emit(rec)
        if rec["ok"]:
            print(f"  {d}D {dist:<7} n={n:<8} seed {seed} {tool:<16} {rec['seconds']:9.3f} s "
                  f"{rec['simplices']:>10} simplices {rec['peak_kb'] / 1024:8.1f} MiB"
                  + ("  (resumed)" if kept else ""), file=sys.stderr)
        else:
            print(f"  {d}D {dist:<7} n={n:<8} seed {seed} {tool:<16} FAILED: {rec['error']}",
                  file=sys.stderr)
        return rec

    def config(self, d, dist, sizes):
        """Every size of one (d, dist): rounds interleaved, tools dropped when too slow."""
        tools = [t for t in sd.tools_for(d) if t in self.tools]
        dropped = set()
        history = {t: [] for t in tools}  # (sites, median seconds) per finished size
        for i, n in enumerate(sizes):
            active = [t for t in tools if t not in dropped]
            self.run("none", d, dist, n, self.a.seed)  # the input's own memory, once
            failed = set()
            for r in range(self.a.rounds):
                order = active[r % len(active):] + active[:r % len(active)] if active else []
                for t in order:
                    if t in failed:
                        continue
                    if not self.run(t, d, dist, n, self.a.seed + r)["ok"]:
                        failed.add(t)  # a timeout or crash would repeat: not again
            for t in active:
                times = [x["seconds"] for x in self.records
                         if x["kind"] == "run" and x["ok"] and x["tool"] == t and x["d"] == d
                         and x["dist"] == dist and x["n"] == n]
                reason = None
                if t in failed:
                    reason = f"failed or timed out at n={sd.fmt_n(n)}"
                elif times:
                    med = statistics.median(times)
                    history[t].append((n, med))
                    if med > self.a.budget:
                        reason = (f"median {sd.fmt_s(med)} s at n={sd.fmt_n(n)} over the "
                                  f"{self.a.budget:g} s budget")
                    elif i + 1 < len(sizes):
                        p = predicted(history[t], sizes[i + 1])
                        if p > 2 * self.a.budget:
                            reason = (f"predicted {sd.fmt_s(p)} s at n={sd.fmt_n(sizes[i + 1])} "
                                      f"(over twice the {self.a.budget:g} s budget)")
                if reason and i + 1 < len(sizes):
                    dropped.add(t)
                    self.emit({"kind": "skip", "tool": t, "d": d, "dist": dist,
                               "n": sizes[i + 1], "reason": reason})
                    print(f"  {t} dropped for {d}D {dist} n >= {sizes[i + 1]}: {reason}",
                          file=sys.stderr)


def write_csv(path, records):
    """Every run, one row: the raw data behind the report."""
    cols = ["d", "dist", "n", "sites", "tool", "seed", "ok", "seconds", "cpu", "simplices",
            "peak_kb", "pred_calls", "pred_filter", "pred_grid", "pred_residue", "pred_exact",
            "pred_zero", "pred_sos_general", "error"]
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for r in records:
            if r.get("kind") == "run":
                w.writerow([r.get(c, "") for c in cols])


def machine_facts(exe):
    p = subprocess.run([exe, "info"], capture_output=True, text=True, check=True)
    return [line for line in p.stdout.splitlines() if line.strip()]


def main(argv):
    a = parse_args(argv)
    if not a.report_only:
        plan = QUICK if a.quick else FULL
        previous = []
        if a.resume and os.path.exists(a.results):
            previous = sd.Results.load(a.results).runs
        tools = built_tools(a.exe)
        meta = {"kind": "meta", "quick": a.quick, "rounds": a.rounds, "budget": a.budget,
                "timeout": a.timeout, "seed": a.seed, "dims": a.dims, "dists": a.dists,
                "tools": tools, "commit": a.commit, "build_dir": a.build_dir,
                "command": a.command, "facts": machine_facts(a.exe),
                "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")}
        t0 = time.time()
        with open(a.results, "w", encoding="utf-8") as out:
            sweep = Sweep(a, tools, out)
            sweep.done = {(r["tool"], r["d"], r["dist"], r["n"], r["seed"]): r
                          for r in previous if r["ok"]}
            sweep.emit(meta)
            for d in a.dims:
                for dist in a.dists:
                    sizes = plan[dist].get(d)
                    if sizes:
                        print(f"scaling: {d}D {dist}: n = {sizes}", file=sys.stderr)
                        sweep.config(d, dist, sizes)
            meta["seconds"] = time.time() - t0
            sweep.emit(dict(meta, kind="meta_end"))
    records = []
    with open(a.results, encoding="utf-8") as f:
        records = [json.loads(line) for line in f if line.strip()]
    end = next((r for r in records if r.get("kind") == "meta_end"), None)
    if end:  # the sweep's total time belongs in the meta record the report reads
        for r in records:
            if r.get("kind") == "meta":
                r["seconds"] = end.get("seconds")
    res = sd.Results(records)
    docs = os.path.dirname(os.path.abspath(a.out))
    os.makedirs(docs, exist_ok=True)
    write_csv(os.path.join(docs, "bench-scaling-runs.csv"), records)
    scaling_plots.write_all(res, docs)
    status = scaling_report.write(res, a.out)
    print(f"scaling: wrote {a.out}, {docs}/bench-scaling-*.svg, {docs}/bench-scaling-runs.csv",
          file=sys.stderr)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
