// bench_predicates_inputs.cpp — the input tuples: random (every coordinate uniform in
// [0,1)) and near-degenerate (orient: the last point an affine combination of the others
// moved by 1 ulp; insphere: points on the unit sphere rounded to doubles).
#include "bench_predicates.h"

#include <cmath>

namespace
{

const double kTwoPi = 6.283185307179586476925286766559;

} // namespace

// Writes one tuple of np points of dimension d into out.
void gen_tuple(Rng &r, Pred p, Input in, int d, double *out)
{
    const int np = p == Pred::orient ? d + 1 : d + 2;
    if (in == Input::random) {
        for (int i = 0; i < np * d; ++i) out[i] = r.u01();
        return;
    }
    if (p == Pred::orient) {
        // d points uniform; the last an affine combination of them, rounded, then one
        // coordinate moved by 1 ulp up or down.
        for (int i = 0; i < d * d; ++i) out[i] = r.u01();
        double t[8];
        for (int j = 1; j < d; ++j) t[j] = r.u01();
        double *q = out + d * d;
        for (int c = 0; c < d; ++c) {
            double v = out[c];
            for (int j = 1; j < d; ++j) v += t[j] * (out[j * d + c] - out[c]);
            q[c] = v;
        }
        uint64_t b = r.bits();
        int c = static_cast<int>(b % static_cast<uint64_t>(d));
        q[c] = std::nextafter(q[c], (b >> 32) & 1 ? 2.0 : -2.0);
        return;
    }
    // insphere: d+2 points on the unit sphere, rounded.
    for (int i = 0; i < np; ++i) {
        double *q = out + i * d;
        if (d == 2) {
            double th = kTwoPi * r.u01();
            q[0] = std::cos(th);
            q[1] = std::sin(th);
        } else if (d == 3) {
            double z = 2.0 * r.u01() - 1.0, th = kTwoPi * r.u01();
            double s = std::sqrt(1.0 - z * z);
            q[0] = s * std::cos(th);
            q[1] = s * std::sin(th);
            q[2] = z;
        } else {
            double n2 = 0;
            do {
                n2 = 0;
                for (int c = 0; c < d; ++c) {
                    q[c] = r.gauss();
                    n2 += q[c] * q[c];
                }
            } while (n2 < 1e-6);
            double inv = 1.0 / std::sqrt(n2);
            for (int c = 0; c < d; ++c) q[c] *= inv;
        }
    }
}
