"""The point sets of qhull_golden.py: rbox specifications read from Qhull's tests, normalized,
capped per dimension, run through rbox and deduplicated; also how the programs are run."""

import hashlib
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXACT_CHECK = os.path.join(HERE, "exact_check.py")

# Largest point count per dimension (keeps a run of all sets at about a minute on one core).
CAP = {2: 2000, 3: 1000, 4: 400, 5: 150, 6: 80, 7: 50, 8: 30}
# LH_TEST_SCALE (the sanitizer run sets 0.2) shrinks the caps, never below 2d + 2 points.
_SCALE = float(os.environ.get("LH_TEST_SCALE", "1"))
CAP = {d: max(2 * d + 2, int(c * _SCALE)) for d, c in CAP.items()}
TIMEOUT = 120


def run(cmd, data, timeout=TIMEOUT):
    """Runs cmd (a list) with data on standard input -> (returncode, stdout, stderr)."""
    try:
        p = subprocess.run(cmd, input=data, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           timeout=timeout, universal_newlines=True)
    except subprocess.TimeoutExpired:
        return 124, "", "timed out after %d s" % timeout
    return p.returncode, p.stdout, p.stderr


def qhull_error(err):
    m = re.search(r"QH(\d{4})", err)
    return ("QH" + m.group(1)) if m else (err.strip().splitlines() or ["failed"])[0][:60]


# ---------------------------------------------------------------------------------------------
# the sets


def read_specs(path):
    specs, in_a = [], False
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("# === Section A"):
                in_a = True
                continue
            if line.startswith("# === Section"):
                if in_a:
                    break
                continue
            if not in_a or line.startswith("#") or not line.strip():
                continue
            parts = line.rstrip("\n").split("\t", 1)
            if len(parts) == 2:
                specs.append(parts[1].strip())
    return specs


TOKEN = re.compile(r"^([0-9]+|[A-Za-z][-+0-9.,eE]*)$")


def normalize(spec):
    """-> (tokens after 'rbox', None) or (None, why skipped)."""
    toks = spec.split()
    if not toks or toks[0] != "rbox":
        return None, "not an rbox command"
    toks = toks[1:]
    if any(c in spec for c in "'\"|"):
        return None, "quoted arguments (a user_eg pipeline)"
    for t in toks:
        if not TOKEN.match(t) or (t[0].isalpha() and len(t) > 1 and t[1].isalpha()):
            return None, "not an rbox option: %s" % t
        if t[0] == "h":
            return None, "h (Geomview/homogeneous output)"
    return ["t1" if t == "t" else t for t in toks], None


def cap_count(toks, d):
    out = []
    for t in toks:
        if t.isdigit() and int(t) > CAP[d]:
            t = str(CAP[d])
        out.append(t)
    return out


def parse_points(text):
    lines = text.split("\n")
    head = lines[0].split()
    d = int(head[0])
    n = int(lines[1].split()[0])
    pts = []
    for ln in lines[2:2 + n]:
        pts.append([float(x) for x in ln.split()])
    if len(pts) != n or any(len(p) != d for p in pts):
        raise ValueError("malformed rbox output")
    return d, pts


def make_sets(args, log):
    sets, seen, skipped = [], {}, []
    for spec in read_specs(args.invocations):
        toks, why = normalize(spec)
        if toks is None:
            skipped.append((spec, why))
            continue
        rc, out, err = run([args.rbox] + toks, "")
        if rc != 0 or not out.strip():
            skipped.append((spec, "rbox failed: %s" % (err.strip().splitlines() or ["?"])[0]))
            continue
        try:
            d = int(out.split()[0])
        except ValueError:
            skipped.append((spec, "unreadable rbox output"))
            continue
        if d < 2 or d > 8:
            skipped.append((spec, "%d dimensions" % d))
            continue
        capped = cap_count(toks, d)
        if capped != toks:
            rc, out, err = run([args.rbox] + capped, "")
            if rc != 0:
                skipped.append((spec, "rbox failed after capping"))
                continue
        try:
            d, pts = parse_points(out)
        except (ValueError, IndexError):
            skipped.append((spec, "unreadable rbox output"))
            continue
        body = "\n".join(out.split("\n")[1:])
        key = hashlib.sha1(("%d\n" % d + body).encode()).hexdigest()
        name = "rbox " + " ".join(capped)
        if key in seen:
            continue
        seen[key] = name
        # the point file as lifthull and Qhull read it (rbox's own text)
        sets.append({"name": name, "spec": spec, "d": d, "pts": pts, "text": out})
    for spec, why in skipped:
        log("SKIP  %-34s %s" % (spec, why))
    return sets, skipped


# ---------------------------------------------------------------------------------------------
# lifthull's output through exact_check.py; Qhull's volume (FA)


def exact_check_i(args, set_text, i_text, tmp):
    pf = os.path.join(tmp, "pts.txt")
    sf = os.path.join(tmp, "simp.txt")
    with open(pf, "w") as f:
        f.write(set_text)
    with open(sf, "w") as f:
        f.write(i_text)
    cmd = [sys.executable, EXACT_CHECK, pf, sf]
    if args.limit:
        cmd += ["--limit", str(args.limit)]
    rc, out, err = run(cmd, "")
    last = (out.strip().splitlines() or [err.strip()])[-1]
    return rc == 0, last


def qhull_volume(args, text):
    rc, out, err = run([args.qconvex, "FA", "s"], text)
    m = re.search(r"Total volume:\s*([-+0-9.eE]+)", out + err)
    return float(m.group(1)) if rc == 0 and m else None
