"""svg_plot.py — small SVG line charts with the Python standard library only (no
matplotlib: the benchmark machines cannot install it). A figure is a grid of panels
sharing one legend; each panel has linear or logarithmic axes (log: a tick and label
per decade, unlabelled ticks at 2..9 times it), light grid lines, and one polyline
with markers per series. Used by scaling_plots.py for docs/bench-scaling-*.svg.
"""

import math
from xml.sax.saxutils import escape

FONT = 'font-family="DejaVu Sans, Arial, Helvetica, sans-serif"'
SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


class Series:
    """One line: points (x, y) drawn in order; a y of None breaks the line."""

    def __init__(self, label, points, color, dashed=False):
        self.label, self.points, self.color, self.dashed = label, points, color, dashed


class Panel:
    """One chart of the grid. xticks: explicit (value, label) ticks for a linear x axis."""

    def __init__(self, title, series, xlabel, ylabel, xlog=True, ylog=True, xticks=None):
        self.title, self.series = title, series
        self.xlabel, self.ylabel = xlabel, ylabel
        self.xlog, self.ylog, self.xticks = xlog, ylog, xticks


def decade_label(k):
    """10^k as text: plain digits from 0.01 to 1000, else 10 with a superscript."""
    if -2 <= k <= 3:
        return f"{10.0 ** k:g}"
    return "10" + str(k).translate(SUPERSCRIPT)


class Axis:
    """Maps data values to pixels along [p0, p1] (p1 < p0 for a y axis)."""

    def __init__(self, values, log, p0, p1, ticks=None):
        self.log, self.p0, self.p1 = log, p0, p1
        vals = [v for v in values if v is not None and (v > 0 or not log)]
        if not vals:
            vals = [1.0, 10.0] if log else [0.0, 1.0]
        lo, hi = min(vals), max(vals)
        if log:
            self.lo, self.hi = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
            if self.hi == self.lo:
                self.hi += 1
        else:
            if ticks:
                lo, hi = min(lo, ticks[0][0]), max(hi, ticks[-1][0])
            pad = 0.05 * (hi - lo or 1.0)
            self.lo, self.hi = lo - pad, hi + pad
        self.ticks = ticks

    def pos(self, v):
        t = math.log10(v) if self.log else v
        return self.p0 + (t - self.lo) / (self.hi - self.lo) * (self.p1 - self.p0)

    def major(self):
        """(value, label) of the labelled ticks."""
        if not self.log:
            if self.ticks:
                return self.ticks
            step = 10 ** math.floor(math.log10((self.hi - self.lo) / 2 or 1))
            first = math.ceil(self.lo / step) * step
            out, v = [], first
            while v <= self.hi:
                out.append((v, f"{v:g}"))
                v += step
            return out
        span = self.hi - self.lo
        every = 1 if span <= 7 else 2  # keep labels from colliding on long axes
        return [(10.0 ** k, decade_label(k) if (k - self.lo) % every == 0 else "")
                for k in range(self.lo, self.hi + 1)]

    def minor(self):
        if not self.log or self.hi - self.lo > 7:
            return []
        return [m * 10.0 ** k for k in range(self.lo, self.hi) for m in range(2, 10)]


def _text(x, y, s, size=11, anchor="middle", extra=""):
    return (f'<text x="{x:.1f}" y="{y:.1f}" {FONT} font-size="{size}" '
            f'text-anchor="{anchor}"{extra}>{escape(s)}</text>')


def _panel(p, x0, y0, w, h):
    """SVG elements of panel p with its outer box at (x0, y0), size w x h."""
    left, right, top, bottom = 56, 10, 22, 40
    ax0, ax1, ay0, ay1 = x0 + left, x0 + w - right, y0 + h - bottom, y0 + top
    xs = [x for s in p.series for x, y in s.points if y is not None]
    ys = [y for s in p.series for x, y in s.points if y is not None]
    xa = Axis(xs, p.xlog, ax0, ax1, p.xticks)
    ya = Axis(ys, p.ylog, ay0, ay1)
    out = [_text((ax0 + ax1) / 2, y0 + 14, p.title, 12, extra=' font-weight="bold"')]
    for v in xa.minor():
        out.append(f'<line x1="{xa.pos(v):.1f}" y1="{ay0}" x2="{xa.pos(v):.1f}" y2="{ay1}" '
                   'stroke="#f0f0f0"/>')
    for v in ya.minor():
        out.append(f'<line x1="{ax0}" y1="{ya.pos(v):.1f}" x2="{ax1}" y2="{ya.pos(v):.1f}" '
                   'stroke="#f0f0f0"/>')
    for v, label in xa.major():
        x = xa.pos(v)
        out.append(f'<line x1="{x:.1f}" y1="{ay0}" x2="{x:.1f}" y2="{ay1}" stroke="#d8d8d8"/>')
        out.append(f'<line x1="{x:.1f}" y1="{ay0}" x2="{x:.1f}" y2="{ay0 + 4}" stroke="#333"/>')
        if label:
            out.append(_text(x, ay0 + 15, label, 10))
    for v, label in ya.major():
        y = ya.pos(v)
        out.append(f'<line x1="{ax0}" y1="{y:.1f}" x2="{ax1}" y2="{y:.1f}" stroke="#d8d8d8"/>')
        out.append(f'<line x1="{ax0 - 4}" y1="{y:.1f}" x2="{ax0}" y2="{y:.1f}" stroke="#333"/>')
        if label:
            out.append(_text(ax0 - 6, y + 3.5, label, 10, "end"))
    out.append(f'<rect x="{ax0}" y="{ay1}" width="{ax1 - ax0}" height="{ay0 - ay1}" '
               'fill="none" stroke="#333"/>')
    out.append(_text((ax0 + ax1) / 2, y0 + h - 8, p.xlabel, 10))
    cy = (ay0 + ay1) / 2
    out.append(_text(x0 + 12, cy, p.ylabel, 10, extra=f' transform="rotate(-90 {x0 + 12} {cy:.1f})"'))
    for s in p.series:
        dash = ' stroke-dasharray="5,3"' if s.dashed else ""
        run = []
        for x, y in s.points + [(None, None)]:
            if y is None or x is None:
                if len(run) > 1:
                    pts = " ".join(f"{a:.1f},{b:.1f}" for a, b in run)
                    out.append(f'<polyline points="{pts}" fill="none" stroke="{s.color}" '
                               f'stroke-width="1.8"{dash}/>')
                run = []
                continue
            run.append((xa.pos(x), ya.pos(y)))
            out.append(f'<circle cx="{run[-1][0]:.1f}" cy="{run[-1][1]:.1f}" r="2.6" '
                       f'fill="{s.color}"/>')
    return out


def _legend(entries, x0, y0, width):
    """entries: (label, color, dashed); laid out in rows across width. Returns (svg, height)."""
    out, x, y = [], x0, y0
    for label, color, dashed in entries:
        w = 40 + 6.2 * len(label)  # line, gap, text at ~6.2 px a character
        if x + w > x0 + width and x > x0:
            x, y = x0, y + 18
        dash = ' stroke-dasharray="5,3"' if dashed else ""
        out.append(f'<line x1="{x:.1f}" y1="{y:.1f}" x2="{x + 22:.1f}" y2="{y:.1f}" '
                   f'stroke="{color}" stroke-width="2"{dash}/>')
        out.append(f'<circle cx="{x + 11:.1f}" cy="{y:.1f}" r="2.6" fill="{color}"/>')
        out.append(_text(x + 27, y + 4, label, 11, "start"))
        x += w
    return out, y - y0 + 18


def write(path, title, panels, legend, cols=3, panel_w=300, panel_h=230, note=None):
    """Writes the figure: title, legend (label, color, dashed) entries, panels in a grid."""
    cols = max(1, min(cols, len(panels)))
    rows = (len(panels) + cols - 1) // cols
    width = cols * panel_w + 20
    legend_svg, legend_h = _legend(legend, 20, 44, width - 40)
    top = 44 + legend_h
    height = top + rows * panel_h + (26 if note else 10)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           _text(width / 2, 22, title, 15, extra=' font-weight="bold"')]
    out += legend_svg
    for i, p in enumerate(panels):
        r, c = divmod(i, cols)
        out += _panel(p, 10 + c * panel_w, top + r * panel_h, panel_w, panel_h)
    if note:
        out.append(_text(width / 2, height - 10, note, 10, extra=' fill="#555"'))
    out.append("</svg>")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")
