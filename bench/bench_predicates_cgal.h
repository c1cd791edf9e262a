// bench_predicates_cgal.h — the CGAL side of bench_predicates: points built from the
// pool's doubles, and each predicate as an Epick (Epick_d<4> in 4D) functor over one
// tuple; then the timed and the sign-recording passes over a pool, for both libraries.
#ifndef LH_BENCH_PREDICATES_CGAL_H
#define LH_BENCH_PREDICATES_CGAL_H

#include "bench_predicates.h"

#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

#define NOINLINE __attribute__((noinline))

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using KD4 = CGAL::Epick_d<CGAL::Dimension_tag<4>>;

// ---- CGAL adapters ----------------------------------------------------------------

template <int D> struct CgalPoint;
template <> struct CgalPoint<2> {
    using type = K::Point_2;
    static type make(const double *c)
    {
        return type(c[0], c[1]);
    }
};
template <> struct CgalPoint<3> {
    using type = K::Point_3;
    static type make(const double *c)
    {
        return type(c[0], c[1], c[2]);
    }
};
template <> struct CgalPoint<4> {
    using type = KD4::Point_d;
    static type make(const double *c)
    {
        return type(c, c + 4);
    }
};

template <int D, Pred P> struct CgalPred;
template <> struct CgalPred<2, Pred::orient> {
    static constexpr const char *name = "Epick Orientation_2";
    K::Orientation_2 f = K().orientation_2_object();
    int operator()(const K::Point_2 *a) const
    {
        return static_cast<int>(f(a[0], a[1], a[2]));
    }
};
template <> struct CgalPred<3, Pred::orient> {
    static constexpr const char *name = "Epick Orientation_3";
    K::Orientation_3 f = K().orientation_3_object();
    int operator()(const K::Point_3 *a) const
    {
        return static_cast<int>(f(a[0], a[1], a[2], a[3]));
    }
};
template <> struct CgalPred<4, Pred::orient> {
    static constexpr const char *name = "Epick_d<4> Orientation_d";
    KD4::Orientation_d f = KD4().orientation_d_object();
    int operator()(const KD4::Point_d *a) const
    {
        return static_cast<int>(f(a, a + 5));
    }
};
template <> struct CgalPred<2, Pred::insphere> {
    static constexpr const char *name = "Epick Side_of_oriented_circle_2";
    K::Side_of_oriented_circle_2 f = K().side_of_oriented_circle_2_object();
    int operator()(const K::Point_2 *a) const
    {
        return static_cast<int>(f(a[0], a[1], a[2], a[3]));
    }
};
template <> struct CgalPred<3, Pred::insphere> {
    static constexpr const char *name = "Epick Side_of_oriented_sphere_3";
    K::Side_of_oriented_sphere_3 f = K().side_of_oriented_sphere_3_object();
    int operator()(const K::Point_3 *a) const
    {
        return static_cast<int>(f(a[0], a[1], a[2], a[3], a[4]));
    }
};
template <> struct CgalPred<4, Pred::insphere> {
    static constexpr const char *name = "Epick_d<4> Side_of_oriented_sphere_d";
    KD4::Side_of_oriented_sphere_d f = KD4().side_of_oriented_sphere_d_object();
    int operator()(const KD4::Point_d *a) const
    {
        return static_cast<int>(f(a, a + 5, a[5]));
    }
};

// ---- the timed loops ----------------------------------------------------------------

template <int D, Pred P> constexpr int npts()
{
    return P == Pred::orient ? D + 1 : D + 2;
}

template <int D, Pred P> inline int lh_call(lh_pred *ctx, const double *const *pts)
{
    if constexpr (P == Pred::orient)
        return lh_orient(ctx, D, pts);
    else
        return lh_insphere(ctx, D, pts);
}

// One pass over the pool; returns the sum of signs (checksum).
template <int D, Pred P> NOINLINE long lh_pass(lh_pred *ctx, const double *c, size_t n)
{
    constexpr int NP = npts<D, P>();
    const double *ptrs[NP];
    long acc = 0;
    for (size_t i = 0; i < n; ++i) {
        const double *b = c + i * (NP * D);
        for (int j = 0; j < NP; ++j) ptrs[j] = b + j * D;
        acc += lh_call<D, P>(ctx, ptrs);
    }
    return acc;
}

template <int D, Pred P>
NOINLINE long cgal_pass(const CgalPred<D, P> &f, const typename CgalPoint<D>::type *pts, size_t n)
{
    constexpr int NP = npts<D, P>();
    long acc = 0;
    for (size_t i = 0; i < n; ++i) acc += f(pts + i * NP);
    return acc;
}

// The same CGAL pass, but every predicate call goes through an out-of-line function, as
// lifthull's calls do (informational: separates call overhead from predicate cost).
template <int D, Pred P>
NOINLINE int cgal_call_ool(const CgalPred<D, P> &f, const typename CgalPoint<D>::type *a)
{
    return f(a);
}
template <int D, Pred P>
NOINLINE long cgal_pass_ool(const CgalPred<D, P> &f, const typename CgalPoint<D>::type *pts,
                            size_t n)
{
    constexpr int NP = npts<D, P>();
    long acc = 0;
    for (size_t i = 0; i < n; ++i) acc += cgal_call_ool<D, P>(f, pts + i * NP);
    return acc;
}

// Sign-recording passes (untimed).
template <int D, Pred P>
void lh_signs(lh_pred *ctx, const double *c, size_t n, std::vector<signed char> &out)
{
    constexpr int NP = npts<D, P>();
    const double *ptrs[NP];
    out.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const double *b = c + i * (NP * D);
        for (int j = 0; j < NP; ++j) ptrs[j] = b + j * D;
        out[i] = static_cast<signed char>(lh_call<D, P>(ctx, ptrs));
    }
}
template <int D, Pred P>
void cgal_signs(const CgalPred<D, P> &f, const typename CgalPoint<D>::type *pts, size_t n,
                std::vector<signed char> &out)
{
    constexpr int NP = npts<D, P>();
    out.resize(n);
    for (size_t i = 0; i < n; ++i) out[i] = static_cast<signed char>(f(pts + i * NP));
}

#endif
