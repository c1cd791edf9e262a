#!/usr/bin/env python3
"""gen_filters.py -- writes lib/internal/lh_filter.gen.h, the floating-point filters of
lifthull's predicates, one straight-line function per predicate and dimension, with
error bounds derived here in exact rational arithmetic.

    python3 lib/gen/gen_filters.py [--check] OUTPUT

--check compares instead of writing and exits 1 when OUTPUT differs (CI runs it).

The filter for an m x m determinant (orient_k: m = k, rows p_i - p_0; insphere_d:
m = d + 1, rows (p_i - p_0, |p_i - p_0|^2)) evaluates it by Laplace expansion along
columns with every minor of the leading columns computed once per row subset, so
the 2D..5D code is what one would write by hand. Error bound (Higham, "Accuracy and
Stability of Numerical Algorithms", 2nd ed., 3.1 and 3.3): each of the m! products of
the expansion carries at most g roundings,
    g = sum_{s=2..m} s        (one product and s-1 additions at level s)
      + m                     (orient: the m differences p_i - p_0)
      + (m - 1) + (d + 2)     (insphere: d differences; the lifted entry: squares of
                               rounded differences, their rounding, d-1 additions)
so |computed - exact| <= gamma_g * m! * prod_j M_j, gamma_g = g u / (1 - g u),
u = 2^-53, M_j the largest exact magnitude in column j. M_j is taken from the
rounded entries (a factor 1/(1-u) per coordinate column, 1/(1-gamma_(d+2)) for the
lifted one) and the bound product is itself rounded (a factor 1/(1-u) per factor).
The filter answers only when every M_j lies in [2^-E, 2^E] (lifted column: squared),
E = floor(900 / degree): then no product overflows and underflow adds at most 2^-90
of the bound, covered by the extra factor (1 + 2^-40). A zero column means an exact
zero when it is a coordinate column. Otherwise the exact stage decides. See docs/predicates.md.
"""
import math
import re
import sys
from fractions import Fraction

import gen_check

U = Fraction(1, 2**53)


def gamma(g):
    return g * U / (1 - g * U)


def round_up(x):
    f = float(x)
    if Fraction(f) < x:
        f = math.nextafter(f, math.inf)
    return f


def bound_constant(m, lifted, d):
    g = m * (m + 1) // 2 - 1
    g += (m - 1) + (d + 2) if lifted else m
    c = math.factorial(m) * gamma(g) / (1 - U) ** (2 * m) * (1 + Fraction(1, 2**40))
    if lifted:
        c /= 1 - gamma(d + 2)
    return round_up(c), g


def laplace(m, out):
    """Emits minors mS_MASK of the leading S columns; returns the full determinant's name."""
    def name(mask, s):
        if s == 1:
            return "a%d_0" % (mask.bit_length() - 1)
        return "m%d_%x" % (s, mask)

    for s in range(2, m + 1):
        for mask in range(1 << m):
            if bin(mask).count("1") != s:
                continue
            terms = []
            pos = 0
            for r in range(m):
                if mask & (1 << r):
                    sign = "-" if (pos + s - 1) & 1 else "+"
                    terms.append((sign, "a%d_%d * %s" % (r, s - 1, name(mask ^ (1 << r), s - 1))))
                    pos += 1
            expr = ("-" if terms[0][0] == "-" else "") + terms[0][1]
            for sign, t in terms[1:]:
                expr += " %s %s" % (sign, t)
            out.append("    const double %s = %s;" % (name(mask, s), expr))
    return name((1 << m) - 1, m)


def hexf(x):
    return float(x).hex()


def emit_entries(m, dim, lifted, out):
    """The matrix entries a<i>_<j>: p_(i+1) - p_0, and the lifted |p_(i+1) - p_0|^2."""
    out.append("    const double *p0 = p[0];")
    for i in range(m):
        pt = i + 1
        out.append("    const double *p%d = p[%d];" % (pt, pt))
        for j in range(dim):
            out.append("    const double a%d_%d = p%d[%d] - p0[%d];" % (i, j, pt, j, j))
        if lifted:
            sq = " + ".join("a%d_%d * a%d_%d" % (i, j, i, j) for j in range(dim))
            out.append("    const double a%d_%d = %s;" % (i, dim, sq))


def emit_filter(kind, dim, out):
    lifted = kind == "insphere"
    m = dim + 1 if lifted else dim
    npts = dim + 2 if lifted else dim + 1
    degree = dim + 2 if lifted else dim
    e = 900 // degree
    c, g = bound_constant(m, lifted, dim)
    out.append("")
    out.append("/* %s_%d: %dx%d determinant, %d roundings per term, E = %d. */"
               % (kind, dim, m, m, g, e))
    out.append("static inline int lh__%s_filter_%d(const double *const *p, int *sign, double *det, double *err)" % (kind, dim))
    out.append("{")
    if not lifted and dim == 1:
        out.append("    /* Rounding is monotone and x - y rounds to 0 only when x == y. */")
        out.append("    (void)det;")
        out.append("    (void)err;")
        out.append("    *sign = (p[1][0] > p[0][0]) - (p[1][0] < p[0][0]);")
        out.append("    return 1;")
        out.append("}")
        return
    emit_entries(m, dim, lifted, out)
    for j in range(m):
        out.append("    double M%d = fabs(a0_%d);" % (j, j))
        for i in range(1, m):
            out.append("    if (fabs(a%d_%d) > M%d) M%d = fabs(a%d_%d);" % (i, j, j, j, i, j))
    lo, hi = hexf(2.0 ** -e), hexf(2.0 ** e)
    lo2, hi2 = hexf(2.0 ** (-2 * e)), hexf(2.0 ** (2 * e))
    conds = []
    for j in range(m):
        if lifted and j == dim:
            conds.append("!(M%d >= %s && M%d <= %s)" % (j, lo2, j, hi2))
        else:
            conds.append("!(M%d >= %s && M%d <= %s)" % (j, lo, j, hi))
    out.append("    if (" + " ||\n        ".join(conds) + ") {")
    # Coordinate columns hold exact differences (a difference rounds to 0 only when
    # it is 0), so a zero there is an exact zero column; the lifted column is rounded
    # (its squares may underflow) and proves nothing.
    zeros = " || ".join("M%d == 0" % j for j in range(dim))
    out.append("        if (%s) { /* a zero coordinate column: det is exactly 0 */" % zeros)
    out.append("            *sign = 0;")
    out.append("            return 1;")
    out.append("        }")
    out.append("        *err = -1; /* no bound outside the band */")
    out.append("        return 0;")
    out.append("    }")
    det = laplace(m, out)
    prod = " * ".join("M%d" % j for j in range(m))
    out.append("    const double eb = %s * %s; /* %.17g */" % (hexf(c), prod, c))
    out.append("    if (%s > eb) { *sign = 1; return 1; }" % det)
    out.append("    if (%s < -eb) { *sign = -1; return 1; }" % det)
    out.append("    *det = %s;" % det)
    out.append("    *err = eb;")
    out.append("    return 0;")
    out.append("}")


def emit_static(kind, dim, out):
    """The determinant against a bound valid for every call of one computation.

    Over a fixed set of points, every computed entry of column j is at most S_j in
    magnitude, S_j = fl(max - min) of coordinate j over the set (rounding is
    monotone), and the lifted one at most fl(sum fl(S_j^2)) summed in the entries'
    order. The dynamic bound c * prod M_j is monotone in the M_j, so c * prod S_j
    (rounded as the dynamic one) bounds the error of every call: when every S_j lies
    in the band of the dynamic filter, its derivation holds with S_j in place of M_j
    (no product overflows; underflow stays below 2^-90 of the bound). The caller
    computes that bound once (LH__<KIND>_C_<d>, LH__<KIND>_E_<d>); this function
    skips the per-call magnitudes and answers +1 or -1, or 0 to ask the full filter.
    """
    lifted = kind == "insphere"
    m = dim + 1 if lifted else dim
    degree = dim + 2 if lifted else dim
    c, _ = bound_constant(m, lifted, dim)
    up = kind.upper()
    out.append("")
    out.append("#define LH__%s_C_%d %s /* the bound constant of %s_%d */" % (up, dim, hexf(c), kind, dim))
    out.append("#define LH__%s_E_%d %d /* its band exponent */" % (up, dim, 900 // degree))
    out.append("static inline int lh__%s_static_%d(const double *const *p, double eb)" % (kind, dim))
    out.append("{")
    emit_entries(m, dim, lifted, out)
    det = laplace(m, out)
    out.append("    return (%s > eb) - (%s < -eb);" % (det, det))
    out.append("}")


def emit_static_pair(dim, out):
    """insphere's static filter on two point tuples at once, p in lane 0 and r in
    lane 1 of GNU C vectors of two doubles: each lane performs emit_static's
    operations in the same order (no contraction: -ffp-contract=off), so each sign
    is the one lh__insphere_static_<d> gives, with the same bound. One vector
    instruction does the work of two scalar ones, for the engine's conflict
    tests of two neighbouring cells (hull/insert_impl.h)."""
    m = dim + 1
    scalar = []
    emit_entries(m, dim, True, scalar)
    det = laplace(m, scalar)
    out.append("")
    out.append("static inline void lh__insphere_static2_%d(const double *const *p, const double *const *r, double eb,"
               % dim)
    out.append("                                          int *sign)")
    out.append("{")
    for line in scalar:
        pt = re.match(r"    const double \*p(\d+) = p\[(\d+)\];$", line)
        if pt:
            out.append("    const double *p%s = p[%s], *r%s = r[%s];" % (pt.group(1), pt.group(2), pt.group(1), pt.group(2)))
            continue
        line = line.replace("const double ", "const lh__v2d ")
        out.append(re.sub(r"p(\d+)\[(\d+)\]", r"(lh__v2d){p\1[\2], r\1[\2]}", line))
    for lane in (0, 1):
        out.append("    sign[%d] = (%s[%d] > eb) - (%s[%d] < -eb);" % (lane, det, lane, det, lane))
    out.append("}")


def emit_dispatch(out, comment, name, params, stage, args, dims, fallback):
    """A filter chosen by a dimension given as a value: direct calls, so that each
    is inlined, and a switch that folds away when d is a constant. fallback(kind):
    the default case's expression."""
    out.append("")
    out.extend(comment)
    out.append("static inline int %s(int lifted, int d, const double *const *p%s)" % (name, params))
    out.append("{")
    for kind, ind in (("insphere", "        "), ("orient", "    ")):
        if kind == "insphere":
            out.append("    if (lifted) {")
        out.append(ind + "switch (d) {")
        for d in dims:
            out.append(ind + "case %d: return lh__%s_%s_%d(p%s);" % (d, kind, stage, d, args))
        out.append(ind + "default: return %s;" % fallback(kind))
        out.append(ind + "}")
        if kind == "insphere":
            out.append("    }")
    out.append("}")


def emit_dispatchers(out):
    emit_dispatch(out, ["/* The dynamic filter of orient_d (lifted 0) or insphere_d (lifted 1) for d = 1..8",
                        " * given as a value, as above. */"],
                  "lh__filter_d", ", int *sign,\n                               double *det, double *err",
                  "filter", ", sign, det, err", range(1, 8),
                  lambda kind: "lh__%s_filter_8(p, sign, det, err)" % kind)
    emit_dispatch(out, ["/* The static filter of orient_d or insphere_d for d given as a value: its sign,",
                        " * or 0 when it cannot decide or d (outside 2..5) has none. */"],
                  "lh__static_d", ", double eb", "static", ", eb", range(2, 6), lambda kind: "0")

    out.append("")
    out.append("/* lh__insphere_static_<d> (lifted) on two tuples p and r: sign[0] and sign[1],")
    out.append(" * each 0 when it cannot decide or d (outside 2..5) has none. Paired in one vector")
    out.append(" * evaluation where the compiler has GNU C vectors, else one after the other. */")
    out.append("static inline void lh__static2_d(int d, const double *const *p, const double *const *r, double eb,")
    out.append("                                 int *sign)")
    out.append("{")
    out.append("#ifdef LH__HAVE_V2D")
    out.append("    switch (d) {")
    for d in range(2, 6):
        out.append("    case %d: lh__insphere_static2_%d(p, r, eb, sign); return;" % (d, d))
    out.append("    default: break;")
    out.append("    }")
    out.append("#endif")
    out.append("    sign[0] = lh__static_d(1, d, p, eb);")
    out.append("    sign[1] = lh__static_d(1, d, r, eb);")
    out.append("}")


def generate():
    out = [
        "/* lh_filter.gen.h -- GENERATED by lib/gen/gen_filters.py; do not edit.",
        " * Floating-point filters of orient_1..8 and insphere_1..8 (lifthull.h): each",
        " * returns 1 and sets *sign when the rounded determinant's sign is proven; else 0,",
        " * with *det the rounded determinant and *err a proven bound on its error (or -1",
        " * outside the band where the bound holds). Derivation in the generator. */",
        "#ifndef LH_FILTER_GEN_H",
        "#define LH_FILTER_GEN_H",
        "",
        "#include <math.h>",
    ]
    for k in range(1, 9):
        emit_filter("orient", k, out)
    for d in range(1, 9):
        emit_filter("insphere", d, out)
    out.append("")
    out.append("/* Static filters for the engine's insertion loop (hull/insert_orient.h, lift/insert_lifted.h): one bound per")
    out.append(" * computation, from the column spans of its sites (see the generator). */")
    for k in range(2, 6):
        emit_static("orient", k, out)
    for d in range(2, 6):
        emit_static("insphere", d, out)
    out.append("")
    out.append("#if defined(__GNUC__) /* gcc and clang: vectors of two doubles */")
    out.append("#define LH__HAVE_V2D 1")
    out.append("typedef double lh__v2d __attribute__((vector_size(16)));")
    for d in range(2, 6):
        emit_static_pair(d, out)
    out.append("#endif")
    out.append("")
    out.append("/* The static bound for d = 2..5 from the column spans span[0..d-1] (fl(max - min)")
    out.append(" * of each coordinate over the sites): the constant times the spans (and the")
    out.append(" * lifted span, summed as the entries are), multiplied in the dynamic filter's")
    out.append(" * order; +infinity (never decides) when a span is outside the band. */")
    out.append("static inline double lh__static_bound(int lifted, int d, const double *span)")
    out.append("{")
    out.append("    static const double c[2][6] = {")
    out.append("        {0, 0, LH__ORIENT_C_2, LH__ORIENT_C_3, LH__ORIENT_C_4, LH__ORIENT_C_5},")
    out.append("        {0, 0, LH__INSPHERE_C_2, LH__INSPHERE_C_3, LH__INSPHERE_C_4, LH__INSPHERE_C_5}};")
    out.append("    static const int e[2][6] = {")
    out.append("        {0, 0, LH__ORIENT_E_2, LH__ORIENT_E_3, LH__ORIENT_E_4, LH__ORIENT_E_5},")
    out.append("        {0, 0, LH__INSPHERE_E_2, LH__INSPHERE_E_3, LH__INSPHERE_E_4, LH__INSPHERE_E_5}};")
    out.append("    if (d < 2 || d > 5) return INFINITY;")
    out.append("    const double lo = ldexp(1.0, -e[lifted][d]), hi = ldexp(1.0, e[lifted][d]);")
    out.append("    double b = c[lifted][d], lift = 0;")
    out.append("    for (int j = 0; j < d; j++) {")
    out.append("        if (!(span[j] >= lo && span[j] <= hi)) return INFINITY;")
    out.append("        b *= span[j];")
    out.append("        lift += span[j] * span[j];")
    out.append("    }")
    out.append("    if (lifted && !(lift >= lo * lo && lift <= hi * hi)) return INFINITY;")
    out.append("    return lifted ? b * lift : b;")
    out.append("}")
    emit_dispatchers(out)
    out.append("")
    out.append("#endif")
    return "\n".join(out) + "\n"


def main(argv):
    return gen_check.main(argv, generate)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
